// GPU sorts against std::stable_sort on (key, index) pairs: radix (its passes, and the single-dispatch small
// sort that stands in for them at small counts) must reproduce the stable order exactly, bitonic must sort the
// keys and carry each value with its key.
#include <algorithm>
#include <cstdint>
#include <memory>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "renderer/vk/command_counts.h"
#include "renderer/vk/gpu_buffer.h"
#include "renderer/vk/vk_check.h"
#include "renderer/reorder/gpu_sort.h"
#include "shaders/sort_types.h"
#include "tests/gpu_test.h"

namespace raylab {
namespace {

static_assert(sizeof(gpu::SortRadixPush) == 72);
static_assert(sizeof(gpu::SortScanPush) == 16);
static_assert(sizeof(gpu::SortBitonicPush) == 56);
static_assert(sizeof(gpu::SortCopyPush) == 48);
static_assert(sizeof(gpu::SortOneSweepPush) == 80);
static_assert(sizeof(gpu::SortSmallPush) == 40);

constexpr uint32_t kDead = 0xFFFFFFFFu;
constexpr uint32_t kMaxCount = (1u << 20) + 3;

enum class Dist { Uniform, Sorted, Reversed, Equal, Few, Full32, Dead12 };

const char* distName(Dist d) {
  switch (d) {
    case Dist::Uniform: return "uniform";
    case Dist::Sorted: return "sorted";
    case Dist::Reversed: return "reversed";
    case Dist::Equal: return "equal";
    case Dist::Few: return "few";
    case Dist::Full32: return "full32";
    case Dist::Dead12: return "dead12";
  }
  return "?";
}

uint32_t distKeyBits(Dist d) { return d == Dist::Full32 ? 32 : d == Dist::Dead12 ? 12 : 30; }

std::vector<uint32_t> makeKeys(Dist dist, uint32_t count, uint32_t seed) {
  std::mt19937 rng(seed * 7919u + count);
  const uint32_t bits = distKeyBits(dist);
  const uint32_t mask = bits == 32 ? ~0u : (1u << bits) - 1u;
  std::vector<uint32_t> keys(count);
  for (uint32_t& k : keys) k = rng() & mask;
  switch (dist) {
    case Dist::Sorted: std::sort(keys.begin(), keys.end()); break;
    case Dist::Reversed: std::sort(keys.begin(), keys.end(), std::greater<>()); break;
    case Dist::Equal: std::fill(keys.begin(), keys.end(), 0x2345678u); break;
    case Dist::Few: {
      const uint32_t values[5] = {3, 0x1000000, 0x3FFFFFFF, 77777, 0x155};
      for (uint32_t& k : keys) k = values[rng() % 5];
      break;
    }
    case Dist::Full32:  // the extremes too: 0xFFFFFFFF is a real key at 32 bits
      for (uint32_t& k : keys)
        if (rng() % 16 == 0) k = rng() % 2 ? 0u : kDead;
      break;
    case Dist::Dead12:
      for (uint32_t& k : keys)
        if (rng() % 4 == 0) k = kDead;
      break;
    default: break;
  }
  return keys;
}

// The stable order of (effective key, index): what radix must produce.
std::vector<uint32_t> stableOrder(const std::vector<uint32_t>& keys, uint32_t keyBits) {
  std::vector<uint32_t> order(keys.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
    return gpu::sortEffectiveKey(keys[a], keyBits) < gpu::sortEffectiveKey(keys[b], keyBits);
  });
  return order;
}

// What is sorted with: the portable radix sort's passes, the OneSweep radix variant, the bitonic sort, the
// radix sorter as the lab makes it (the small sort up to SORT_SMALL_MAX pairs, its passes above), and the
// portable passes with one tile a work group. The default groups kDefaultRadixTilesPerGroup (2) tiles
// (Tuning::radixTilesPerGroup: a group's later tiles start where its earlier ones left each digit), so Radix
// checks that; RadixOneTile the loops of one iteration, with no barrier after a group's tile.
enum class Variant { Radix, OneSweep, Bitonic, Small, RadixOneTile, RadixOtherRank };
static_assert(kDefaultRadixTilesPerGroup > 1, "RadixOneTile stands for the shape the default does not take");

SortAlgorithm algorithmOf(Variant v) {
  return v == Variant::Bitonic ? SortAlgorithm::Bitonic : v == Variant::OneSweep ? SortAlgorithm::OneSweep : SortAlgorithm::Radix;
}

std::string variantName(Variant v) {
  switch (v) {
    case Variant::Radix: return "radix";
    case Variant::OneSweep: return "onesweep";
    case Variant::Bitonic: return "bitonic";
    case Variant::Small: return "small";
    case Variant::RadixOneTile: return "radix_one_tile";
    case Variant::RadixOtherRank: return "radix_other_rank";
  }
  return "?";
}

class GpuSortTest : public test::GpuTest {
 protected:
  static GpuSorter& sorter(Variant variant) {
    static std::unique_ptr<GpuSorter> sorters[6];
    auto& slot = sorters[static_cast<int>(variant)];
    if (!slot) {
      GpuSorter::Tuning tuning;
      // The passes are tested at every count, small ones too; Variant::Small keeps the lab's default.
      // (OneSweep's look-back needs forward progress between work groups; where the device does not promise
      // it, lavapipe, the sorter runs one work group per dispatch, so the same shaders are checked.)
      if (variant != Variant::Small) tuning.smallSortMax = 0;
      if (variant == Variant::RadixOneTile) tuning.radixTilesPerGroup = 1;
      // The ranking the default does not take on this device: the ballots where it partitions (NVIDIA), the
      // partition where it has the extension but the default ballots. Only built where the device can run it.
      if (variant == Variant::RadixOtherRank)
        tuning.radixRank = sorter(Variant::Radix).ranksPartitioned() ? RadixRank::Ballot : RadixRank::Partition;
      slot = std::make_unique<GpuSorter>(ctx(), algorithmOf(variant), kMaxCount, tuning);
      EXPECT_EQ(slot->usesOneSweep(), variant == Variant::OneSweep);
    }
    return *slot;
  }
  static GpuSorter& sorter(SortAlgorithm algorithm) {
    return sorter(algorithm == SortAlgorithm::Bitonic ? Variant::Bitonic : Variant::Radix);
  }

  // Sorts (keys, 0..n-1) on the GPU and checks the result against the stable order.
  void sortAndCheck(SortAlgorithm algorithm, const std::vector<uint32_t>& keys, uint32_t keyBits) {
    sortAndCheck(algorithm == SortAlgorithm::Bitonic ? Variant::Bitonic : Variant::Radix, keys, keyBits);
  }
  void sortAndCheck(Variant variant, const std::vector<uint32_t>& keys, uint32_t keyBits) {
    const uint32_t n = static_cast<uint32_t>(keys.size());
    std::vector<uint32_t> values(n);
    std::iota(values.begin(), values.end(), 0u);
    GpuBuffer keyBuf = makeBufferFrom(ctx(), keys);
    GpuBuffer valueBuf = makeBufferFrom(ctx(), values);
    GpuSorter& s = sorter(variant);
    ctx().submitAndWait([&](VkCommandBuffer cmd) { s.record(cmd, keyBuf.address(), valueBuf.address(), n, keyBits); });
    const std::vector<uint32_t> gotKeys = keyBuf.downloadVector<uint32_t>(n);
    const std::vector<uint32_t> gotValues = valueBuf.downloadVector<uint32_t>(n);

    const std::vector<uint32_t> order = stableOrder(keys, keyBits);
    size_t keyMismatches = 0, valueMismatches = 0, firstBad = n;
    std::vector<bool> seen(n, false);
    for (uint32_t i = 0; i < n; ++i) {
      const bool keyOk = gotKeys[i] == keys[order[i]];
      bool valueOk;
      if (variant != Variant::Bitonic) {  // the radix sorts are stable
        valueOk = gotValues[i] == order[i];
      } else {  // a permutation whose every (key, value) pair was in the input
        valueOk = gotValues[i] < n && !seen[gotValues[i]] && keys[gotValues[i]] == gotKeys[i];
        if (gotValues[i] < n) seen[gotValues[i]] = true;
      }
      keyMismatches += !keyOk;
      valueMismatches += !valueOk;
      if ((!keyOk || !valueOk) && firstBad == n) firstBad = i;
    }
    EXPECT_EQ(keyMismatches, 0u) << "first bad index " << firstBad;
    EXPECT_EQ(valueMismatches, 0u) << "first bad index " << firstBad;
  }
};

struct SortCase {
  Variant variant;
  uint32_t count;
  Dist dist;
};

std::string caseName(const ::testing::TestParamInfo<SortCase>& info) {
  return variantName(info.param.variant) + "_" + std::to_string(info.param.count) + "_" + distName(info.param.dist);
}

std::vector<SortCase> allCases() {
  const uint32_t counts[] = {1, 2, 19, 2001, 3103, 11025, 65537, kMaxCount};
  const Dist dists[] = {Dist::Uniform, Dist::Sorted, Dist::Reversed, Dist::Equal,
                        Dist::Few,     Dist::Full32, Dist::Dead12};
  std::vector<SortCase> cases;
  for (Variant v : {Variant::Radix, Variant::OneSweep, Variant::Bitonic, Variant::RadixOneTile})
    for (uint32_t n : counts)
      for (Dist d : dists)
        // Bitonic at 2^20+3 takes seconds on a CPU device: four distributions are enough there, and two for
        // the one-tile passes (the default passes check the rest at that count).
        if (n < kMaxCount || (v == Variant::Radix || v == Variant::OneSweep) ||
            (v == Variant::Bitonic && (d == Dist::Uniform || d == Dist::Reversed || d == Dist::Few || d == Dist::Dead12)) ||
            (v == Variant::RadixOneTile && (d == Dist::Uniform || d == Dist::Dead12)))
          cases.push_back({v, n, d});
  // The small sort at its sizes, its largest, and the first count past it (the passes again).
  for (uint32_t n : {1u, 2u, 19u, 2001u, uint32_t(SORT_SMALL_MAX), uint32_t(SORT_SMALL_MAX) + 1})
    for (Dist d : dists) cases.push_back({Variant::Small, n, d});
  return cases;
}

class GpuSortCases : public GpuSortTest, public ::testing::WithParamInterface<SortCase> {};

TEST_P(GpuSortCases, MatchesStableSort) {
  const SortCase c = GetParam();
  sortAndCheck(c.variant, makeKeys(c.dist, c.count, 1), distKeyBits(c.dist));
}

INSTANTIATE_TEST_SUITE_P(Sort, GpuSortCases, ::testing::ValuesIn(allCases()), caseName);

// The scatter's two rankings sort alike. The default one (kDefaultRadixRank resolved for the device: Auto takes
// subgroupPartitionNV where the device has VK_NV_shader_subgroup_partitioned) runs every case above; this runs
// the other one, where the device can: every count and distribution of the cases above but the largest count,
// and 7, 16 and 23 key bits with dead keys. On a device without the extension (lavapipe) only the ballots run, and the next test
// checks the refusal.
TEST_F(GpuSortTest, OtherRankingMatchesStableSort) {
  if (!ctx().info().subgroupPartitioned) GTEST_SKIP() << ctx().info().name << " lacks VK_NV_shader_subgroup_partitioned";
  EXPECT_NE(sorter(Variant::RadixOtherRank).ranksPartitioned(), sorter(Variant::Radix).ranksPartitioned());
  for (uint32_t n : {1u, 2u, 19u, 2001u, 3103u, 11025u, 65537u})
    for (Dist d : {Dist::Uniform, Dist::Sorted, Dist::Reversed, Dist::Equal, Dist::Few, Dist::Full32, Dist::Dead12}) {
      SCOPED_TRACE(std::to_string(n) + " " + distName(d));
      sortAndCheck(Variant::RadixOtherRank, makeKeys(d, n, 3), distKeyBits(d));
    }
  std::mt19937 rng(5);
  for (uint32_t bits : {7u, 16u, 23u}) {
    std::vector<uint32_t> keys(70001);
    for (uint32_t& k : keys) k = rng() % 5 == 0 ? kDead : rng() & ((1u << bits) - 1u);
    SCOPED_TRACE(std::to_string(bits) + " bits");
    sortAndCheck(Variant::RadixOtherRank, keys, bits);
  }
}

// The default ranking resolves by the device: the partition exactly where the device has the extension (unless
// the lab's default is the ballots), and never for OneSweep, whose passes rank with the ballots.
TEST_F(GpuSortTest, DefaultRankingFollowsTheDevice) {
  EXPECT_EQ(sorter(Variant::Radix).ranksPartitioned(),
            kDefaultRadixRank != RadixRank::Ballot && ctx().info().subgroupPartitioned);
  EXPECT_FALSE(sorter(Variant::OneSweep).ranksPartitioned());
  GpuSorter::Tuning ballot;
  ballot.radixRank = RadixRank::Ballot;
  EXPECT_FALSE(GpuSorter(ctx(), SortAlgorithm::Radix, 1000, ballot).ranksPartitioned());
}

// Where the device lacks the extension, or for another sort, the partitioned ranking is refused with the reason.
TEST_F(GpuSortTest, PartitionedRankingIsRefusedWhereItCannotRun) {
  GpuSorter::Tuning tuning;
  tuning.radixRank = RadixRank::Partition;
  EXPECT_THROW(GpuSorter(ctx(), SortAlgorithm::OneSweep, 1000, tuning), VulkanError);
  if (ctx().info().subgroupPartitioned) GTEST_SKIP() << ctx().info().name << " has the extension: nothing else to refuse";
  try {
    GpuSorter sorter(ctx(), SortAlgorithm::Radix, 1000, tuning);
    ADD_FAILURE() << "accepted on a device without VK_NV_shader_subgroup_partitioned";
  } catch (const VulkanError& e) {
    EXPECT_NE(std::string(e.what()).find("VK_NV_shader_subgroup_partitioned"), std::string::npos) << e.what();
  }
}

// Every key bit below keyBits matters (no pass skipped too many), including pass counts that are odd
// (7 bits: 1 pass, copied back; 16 bits: 3 passes through both scratch sets) and dead keys on top.
class GpuSortBits : public GpuSortTest, public ::testing::WithParamInterface<std::tuple<Variant, uint32_t>> {};

TEST_P(GpuSortBits, KeysBelowTwoToTheBitsSort) {
  const auto [variant, bits] = GetParam();
  std::mt19937 rng(bits);
  const uint32_t mask = bits == 32 ? ~0u : (1u << bits) - 1u;
  for (bool withDead : {false, true}) {
    std::vector<uint32_t> keys(11025);
    for (uint32_t& k : keys) k = (withDead && rng() % 5 == 0) ? kDead : rng() & mask;
    // Keys at the top of the range too, so the highest bit's pass is exercised.
    keys[17] = mask;
    keys[4000] = mask;
    SCOPED_TRACE(withDead ? "with dead keys" : "live keys only");
    sortAndCheck(variant, keys, bits);
  }
}

INSTANTIATE_TEST_SUITE_P(Sort, GpuSortBits,
                         ::testing::Combine(::testing::Values(Variant::Radix, Variant::OneSweep, Variant::Bitonic),
                                            ::testing::Values(1u, 7u, 8u, 9u, 16u, 24u, 30u, 32u)),
                         [](const auto& info) {
                           return variantName(std::get<0>(info.param)) + "_bits" +
                                  std::to_string(std::get<1>(info.param));
                         });

TEST_F(GpuSortTest, PassCountFollowsKeyBits) {
  EXPECT_EQ(GpuSorter::radixPasses(1), 1u);
  EXPECT_EQ(GpuSorter::radixPasses(7), 1u);
  EXPECT_EQ(GpuSorter::radixPasses(8), 2u);
  EXPECT_EQ(GpuSorter::radixPasses(15), 2u);
  EXPECT_EQ(GpuSorter::radixPasses(16), 3u);
  EXPECT_EQ(GpuSorter::radixPasses(30), 4u);
  EXPECT_EQ(GpuSorter::radixPasses(32), 4u);
}

TEST_F(GpuSortTest, ScratchIsReported) {
  EXPECT_GE(sorter(SortAlgorithm::Radix).scratchBytes(), 16ull * kMaxCount);  // two scratch sets
  EXPECT_EQ(sorter(SortAlgorithm::Bitonic).scratchBytes(), 0u);
  EXPECT_GE(sorter(Variant::OneSweep).scratchBytes(), 16ull * kMaxCount);  // two scratch sets
  GpuSorter none(ctx(), SortAlgorithm::None, 1000);
  EXPECT_EQ(none.scratchBytes(), 0u);
  EXPECT_EQ(none.algorithm(), SortAlgorithm::None);
}

TEST_F(GpuSortTest, NoneAndEmptyLeaveBuffersAlone) {
  const std::vector<uint32_t> keys = {5, 3, 9, 1};
  GpuBuffer keyBuf = makeBufferFrom(ctx(), keys);
  GpuBuffer valueBuf = makeBufferFrom(ctx(), keys);
  GpuSorter none(ctx(), SortAlgorithm::None, 4);
  ctx().submitAndWait([&](VkCommandBuffer cmd) {
    none.record(cmd, keyBuf.address(), valueBuf.address(), 4, 8);
    sorter(SortAlgorithm::Radix).record(cmd, keyBuf.address(), valueBuf.address(), 0, 8);
    sorter(SortAlgorithm::Bitonic).record(cmd, keyBuf.address(), valueBuf.address(), 0, 8);
  });
  EXPECT_EQ(keyBuf.downloadVector<uint32_t>(4), keys);
}

TEST_F(GpuSortTest, RejectsCountOverCapacity) {
  GpuSorter small(ctx(), SortAlgorithm::Radix, 100);
  GpuBuffer buf(ctx(), 1024);
  EXPECT_THROW(ctx().submitAndWait([&](VkCommandBuffer cmd) { small.record(cmd, buf.address(), buf.address(), 101, 8); }),
               std::exception);
}

// Keys, values 0..n-1 and a device-side count limit on the device, for the sorts that honour the limit.
struct LimitedSort {
  LimitedSort(const VulkanContext& ctx, const std::vector<uint32_t>& keys, uint32_t limit)
      : ctx(&ctx),
        values(iota(keys.size())),
        keyBuf(makeBufferFrom(ctx, keys)),
        valueBuf(makeBufferFrom(ctx, values)),
        limitBuf(makeBufferFrom(ctx, std::vector<uint32_t>{limit})) {}
  void sortWith(GpuSorter& sorter, uint32_t keyBits) {
    const uint32_t n = static_cast<uint32_t>(values.size());
    ctx->submitAndWait([&](VkCommandBuffer cmd) {
      sorter.record(cmd, keyBuf.address(), valueBuf.address(), n, keyBits, limitBuf.address());
    });
  }
  static std::vector<uint32_t> iota(size_t n) {
    std::vector<uint32_t> v(n);
    std::iota(v.begin(), v.end(), 0u);
    return v;
  }
  const VulkanContext* ctx;
  std::vector<uint32_t> values;
  GpuBuffer keyBuf, valueBuf, limitBuf;
};

// A device-side count limit (the live prefix): the radix sorts' passes (portable and OneSweep) order only
// the first min(count, limit) pairs, stably, and leave every pair past it untouched; odd and even pass counts
// (16 and 12 bits: 3 passes through both scratch sets, 2 passes), limits inside a tile, on a tile edge, on the
// default's group edges (2 and 4 tiles), 0, 1 and past count.
class GpuSortPasses : public GpuSortTest, public ::testing::WithParamInterface<Variant> {};

TEST_P(GpuSortPasses, SortOnlyUpToDeviceCountLimit) {
  const uint32_t n = 70001;
  const uint32_t tile = sorter(GetParam()).radixTile();
  for (uint32_t bits : {12u, 16u}) {
    for (uint32_t limit : {0u, 1u, 777u, 2 * tile, 2 * tile + 1, 3 * tile, 4 * tile, 50000u, n, n + 5}) {
      const std::vector<uint32_t> keys = makeKeys(Dist::Dead12, n, limit + bits);
      LimitedSort in(ctx(), keys, limit);
      std::vector<uint32_t>& values = in.values;
      GpuBuffer &keyBuf = in.keyBuf, &valueBuf = in.valueBuf;
      in.sortWith(sorter(GetParam()), bits);
      const uint32_t sorted = std::min(n, limit);
      std::vector<uint32_t> wantKeys = keys, wantValues = values;
      const std::vector<uint32_t> order =
          stableOrder(std::vector<uint32_t>(keys.begin(), keys.begin() + sorted), bits);
      for (uint32_t i = 0; i < sorted; ++i) {
        wantKeys[i] = keys[order[i]];
        wantValues[i] = order[i];
      }
      SCOPED_TRACE("bits " + std::to_string(bits) + ", limit " + std::to_string(limit));
      EXPECT_EQ(keyBuf.downloadVector<uint32_t>(n), wantKeys);
      EXPECT_EQ(valueBuf.downloadVector<uint32_t>(n), wantValues);
    }
  }
}

// The tile sort (SortAlgorithm::Tile) against its plain C++ reference: each tile of SORT_BITONIC_TILE pairs
// sorted on its own by the effective key (keys equal to the reference; bitonic is not stable, so each tile's
// pairs are compared as a set), the last tile partial, and whole tiles at or past a device-side limit left
// exactly as they were.
TEST_F(GpuSortTest, TileSortSortsEachTileAlone) {
  const uint32_t tile = SORT_BITONIC_TILE, n = 5 * tile + 777;
  GpuSorter tiles(ctx(), SortAlgorithm::Tile, n);
  for (uint32_t limit : {n, 2 * tile + 1, 2 * tile, 0u}) {
    const std::vector<uint32_t> keys = makeKeys(Dist::Dead12, n, limit);
    LimitedSort in(ctx(), keys, limit);
    const std::vector<uint32_t>& values = in.values;
    in.sortWith(tiles, 12);
    const std::vector<uint32_t> gotKeys = in.keyBuf.downloadVector<uint32_t>(n);
    const std::vector<uint32_t> gotValues = in.valueBuf.downloadVector<uint32_t>(n);
    SCOPED_TRACE("limit " + std::to_string(limit));
    for (uint32_t begin = 0; begin < n; begin += tile) {
      const uint32_t end = std::min(n, begin + tile);
      std::vector<std::pair<uint32_t, uint32_t>> want, got;
      for (uint32_t i = begin; i < end; ++i) {
        want.push_back({gpu::sortEffectiveKey(keys[i], 12), i});
        got.push_back({gpu::sortEffectiveKey(gotKeys[i], 12), gotValues[i]});
        ASSERT_LT(gotValues[i], n);
        EXPECT_EQ(gotKeys[i], keys[gotValues[i]]) << "slot " << i << ": a key left its value";
      }
      if (begin >= limit) {  // past the limit: untouched
        EXPECT_EQ(std::vector<uint32_t>(gotValues.begin() + begin, gotValues.begin() + end),
                  std::vector<uint32_t>(values.begin() + begin, values.begin() + end)) << "tile at " << begin;
        continue;
      }
      std::sort(want.begin(), want.end());
      std::vector<std::pair<uint32_t, uint32_t>> gotSorted = got;
      std::sort(gotSorted.begin(), gotSorted.end());
      EXPECT_EQ(gotSorted, want) << "tile at " << begin << " lost or gained pairs";
      for (uint32_t i = 0; i + 1 < got.size(); ++i)
        ASSERT_LE(got[i].first, got[i + 1].first) << "tile at " << begin << ", slot " << begin + i;
    }
  }
}

// Ignoring the low bits: the radix sorts order pairs by the compared key's bits above `ignored` only
// (stable: pairs equal there keep their input order), with dead keys still last, in 1 to 3 passes; with a
// device-side count limit as well (the path sorter passes both).
TEST_P(GpuSortPasses, IgnoreTheLowBitsTheyAreTold) {
  const uint32_t n = 20011, bits = 23;  // the two-point strategy's width: 24 compared bits
  for (uint32_t ignored : {1u, 8u, 9u, 16u, 23u}) {
    const std::vector<uint32_t> keys = makeKeys(Dist::Dead12, n, ignored);
    std::vector<uint32_t> masked(n), values(n);
    for (uint32_t i = 0; i < n; ++i) masked[i] = keys[i] == kDead ? kDead : keys[i] & ((1u << bits) - 1u);
    std::iota(values.begin(), values.end(), 0u);
    GpuBuffer keyBuf = makeBufferFrom(ctx(), masked);
    GpuBuffer valueBuf = makeBufferFrom(ctx(), values);
    const uint32_t limit = ignored == 9 ? 12345 : n;  // one case with a live prefix shorter than the pairs
    GpuBuffer limitBuf = makeBufferFrom(ctx(), std::vector<uint32_t>{limit});
    ctx().submitAndWait([&](VkCommandBuffer cmd) {
      sorter(GetParam()).record(cmd, keyBuf.address(), valueBuf.address(), n, bits, limitBuf.address(), ignored);
    });
    std::vector<uint32_t> order(n);
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.begin() + limit, [&](uint32_t a, uint32_t b) {
      return (gpu::sortEffectiveKey(masked[a], bits) >> ignored) < (gpu::sortEffectiveKey(masked[b], bits) >> ignored);
    });
    EXPECT_EQ(valueBuf.downloadVector<uint32_t>(n), order) << "ignored " << ignored;
  }
}

INSTANTIATE_TEST_SUITE_P(Sort, GpuSortPasses, ::testing::Values(Variant::Radix, Variant::OneSweep, Variant::RadixOneTile),
                         [](const auto& info) { return variantName(info.param); });

// OneSweep runs its work groups together only where the device promises forward progress between them; on
// a CPU device it runs them one a dispatch.
TEST_F(GpuSortTest, OneSweepRunsSeriallyWhereWorkGroupsMayNotProgress) {
  GpuSorter s(ctx(), SortAlgorithm::OneSweep, 1000);
  EXPECT_TRUE(s.usesOneSweep());
  EXPECT_EQ(s.oneSweepSerial(), !GpuSorter::oneSweepSupported(ctx()));
  if (ctx().info().isCpu) {
    EXPECT_TRUE(s.oneSweepSerial());
  }
  EXPECT_FALSE(GpuSorter(ctx(), SortAlgorithm::Radix, 1000).usesOneSweep());
}

// A sorter is reused frame after frame with varying counts; small sorts after a large one must not see its
// leftovers, and a tuned shape (other group size and keys per thread) must sort the same.
TEST_F(GpuSortTest, ReuseAndTunedShapes) {
  for (Variant v : {Variant::Radix, Variant::OneSweep})
    for (uint32_t n : {70000u, 3u, 4099u}) sortAndCheck(v, makeKeys(Dist::Dead12, n, 2), 12);
  const uint32_t sub = ctx().info().subgroupSize;
  for (uint32_t kpt : {1u, 4u, 16u}) {
    GpuSorter::Tuning tuning{std::max(64u, sub), kpt};
    GpuSorter tuned(ctx(), kpt == 4 ? SortAlgorithm::OneSweep : SortAlgorithm::Radix, 50000, tuning);
    const std::vector<uint32_t> keys = makeKeys(Dist::Uniform, 50000, kpt);
    std::vector<uint32_t> values(keys.size());
    std::iota(values.begin(), values.end(), 0u);
    GpuBuffer keyBuf = makeBufferFrom(ctx(), keys);
    GpuBuffer valueBuf = makeBufferFrom(ctx(), values);
    ctx().submitAndWait([&](VkCommandBuffer cmd) { tuned.record(cmd, keyBuf.address(), valueBuf.address(), 50000, 30); });
    EXPECT_EQ(valueBuf.downloadVector<uint32_t>(keys.size()), stableOrder(keys, 30)) << "keys per thread " << kpt;
  }
}

}  // namespace
}  // namespace raylab

namespace raylab {
namespace {

// Every key bit counts in the small sort (1 to 32 bits, dead keys on top), it honours a device-side count
// limit (the pairs past it untouched) and ignores the low bits it is told to, stably, as the passes do.
TEST_F(GpuSortTest, SmallSortBitsLimitAndIgnoredBits) {
  GpuSorter& small = sorter(Variant::Small);
  ASSERT_EQ(small.smallSortMax(), uint32_t(SORT_SMALL_MAX)) << "the device lacks the shared memory: not tested";
  for (uint32_t bits : {1u, 7u, 8u, 9u, 16u, 24u, 30u, 32u}) {
    std::mt19937 rng(bits);
    const uint32_t mask = bits == 32 ? ~0u : (1u << bits) - 1u;
    std::vector<uint32_t> keys(2001);
    for (uint32_t& k : keys) k = rng() % 5 == 0 ? kDead : rng() & mask;
    keys[17] = mask;
    SCOPED_TRACE("bits " + std::to_string(bits));
    sortAndCheck(Variant::Small, keys, bits);
  }
  const uint32_t n = SORT_SMALL_MAX - 7;
  for (uint32_t limit : {0u, 1u, 777u, n, n + 5}) {
    const std::vector<uint32_t> keys = makeKeys(Dist::Dead12, n, limit);
    LimitedSort in(ctx(), keys, limit);
    in.sortWith(small, 12);
    const uint32_t sorted = std::min(n, limit);
    std::vector<uint32_t> wantKeys = keys, wantValues = in.values;
    const std::vector<uint32_t> order = stableOrder(std::vector<uint32_t>(keys.begin(), keys.begin() + sorted), 12);
    for (uint32_t i = 0; i < sorted; ++i) wantKeys[i] = keys[order[i]], wantValues[i] = order[i];
    SCOPED_TRACE("limit " + std::to_string(limit));
    EXPECT_EQ(in.keyBuf.downloadVector<uint32_t>(n), wantKeys);
    EXPECT_EQ(in.valueBuf.downloadVector<uint32_t>(n), wantValues);
  }
  const uint32_t bits = 23;
  for (uint32_t ignored : {1u, 8u, 9u, 23u}) {
    std::vector<uint32_t> keys = makeKeys(Dist::Dead12, n, ignored), values(n);
    for (uint32_t& k : keys) k = k == kDead ? kDead : k & ((1u << bits) - 1u);
    std::iota(values.begin(), values.end(), 0u);
    GpuBuffer keyBuf = makeBufferFrom(ctx(), keys), valueBuf = makeBufferFrom(ctx(), values);
    ctx().submitAndWait([&](VkCommandBuffer cmd) { small.record(cmd, keyBuf.address(), valueBuf.address(), n, bits, 0, ignored); });
    std::stable_sort(values.begin(), values.end(), [&](uint32_t a, uint32_t b) {
      return (gpu::sortEffectiveKey(keys[a], bits) >> ignored) < (gpu::sortEffectiveKey(keys[b], bits) >> ignored);
    });
    EXPECT_EQ(valueBuf.downloadVector<uint32_t>(n), values) << "ignored " << ignored;
  }
}

// The small sort is what its name says: one dispatch up to its threshold, the passes past it and where it is
// turned off (counted as a frame's commands are, command_counts.h).
TEST_F(GpuSortTest, SmallSortIsOneDispatchUpToItsThreshold) {
  auto dispatches = [&](GpuSorter& s, uint32_t n, uint32_t bits = 30) {
    GpuBuffer keys = makeBufferFrom(ctx(), makeKeys(Dist::Uniform, n, 5));
    GpuBuffer values = makeBufferFrom(ctx(), LimitedSort::iota(n));
    CommandTally tally;
    ctx().submitAndWait([&](VkCommandBuffer cmd) {
      CountCommands counting(cmd, tally);
      s.record(cmd, keys.address(), values.address(), n, bits);
    });
    return tally.total().dispatches();
  };
  EXPECT_EQ(dispatches(sorter(Variant::Small), SORT_SMALL_MAX), 1u);
  EXPECT_EQ(dispatches(sorter(Variant::Small), SORT_SMALL_MAX + 1), 3 * GpuSorter::radixPasses(30));
  EXPECT_EQ(dispatches(sorter(Variant::Radix), SORT_SMALL_MAX), 3 * GpuSorter::radixPasses(30));
  // OneSweep: one histogram for all passes, then a dispatch a pass (a dispatch a tile where it runs serially);
  // three passes (16-bit keys: 17 sorted bits) end in the caller's buffers with no copy, one pass is copied.
  GpuSorter& oneSweep = sorter(Variant::OneSweep);
  const uint32_t n = 5 * oneSweep.radixTile() + 1;
  const uint32_t perPass = oneSweep.oneSweepSerial() ? 6 : 1;
  EXPECT_EQ(dispatches(oneSweep, n), 1 + perPass * GpuSorter::radixPasses(30));
  EXPECT_EQ(dispatches(oneSweep, n, 16), 1 + perPass * 3);
  EXPECT_EQ(dispatches(oneSweep, n, 7), 1 + perPass + 1);
  // The portable passes end in the caller's buffers the same way: three passes need no copy, one does.
  EXPECT_EQ(dispatches(sorter(Variant::Radix), n, 16), 3u * 3) << "three portable passes were copied back";
  EXPECT_EQ(dispatches(sorter(Variant::Radix), n, 7), 3u + 1) << "a single portable pass was not copied back";
}

}  // namespace
}  // namespace raylab
