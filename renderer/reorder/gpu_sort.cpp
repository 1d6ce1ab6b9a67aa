#include "renderer/reorder/gpu_sort.h"

#include <algorithm>
#include <bit>
#include <string>
#include <tuple>

#include "renderer/vk/stage_timer.h"
#include "renderer/vk/vk_check.h"
#include "renderer/vk/vk_context.h"
#include "shaders/sort_types.h"

namespace raylab {
namespace {

constexpr uint32_t kScanGroup = 64;  // rows are short (a few hundred tiles); CPU devices pay per invocation
constexpr uint32_t kCopyGroup = 256;
constexpr uint32_t kOneSweepHistogramGroup = 256;
constexpr uint32_t kVendorNvidia = 0x10DE;
constexpr uint32_t kVendorAmd = 0x1002;
// Keys a thread (256 threads a group: a 2048-key tile). Measured on an H100 at 2^21 30-bit pairs with
// `sortbench --n 2097152 --sort all --radix-kpt K`: 8 -> 0.204 ms, 12 -> 0.230, 15 -> 0.237, 20 -> 0.239
// (15 is the published sweet spot of 8-bit reduce-then-scan sorts). Override with --radix-kpt.
constexpr uint32_t kDefaultKeysPerThread = 8;

uint32_t ceilDiv(uint64_t a, uint64_t b) { return static_cast<uint32_t>((a + b - 1) / b); }

uint32_t maxSharedBytes(const VulkanContext& ctx) {
  VkPhysicalDeviceProperties props;
  vkGetPhysicalDeviceProperties(ctx.physicalDevice(), &props);
  return props.limits.maxComputeSharedMemorySize;
}

// Shared memory of sort_radix_scatter for a group size: the larger of the tile (keys and values) and the
// per-subgroup histograms, the two digit tables, the scan scratch of sort_scan.glsl and OneSweep's tile index.
uint64_t scatterSharedBytes(uint32_t group, uint32_t keysPerThread, uint32_t subgroup) {
  uint64_t words = std::max<uint64_t>(2ull * group * keysPerThread, uint64_t(group / subgroup) * SORT_RADIX);
  return 4 * (words + 2 * SORT_RADIX + group + 2);
}

// Splits a dispatch of `groups` work groups at the device's limit; the shader adds groupOffset.
void dispatchSplit(const ComputePipeline& pipeline, VkCommandBuffer cmd, gpu::SortRadixPush push, uint32_t groups,
                   uint32_t maxGroups) {
  for (uint32_t first = 0; first < groups; first += maxGroups) {
    push.groupOffset = first;
    pipeline.dispatchGroups(cmd, push, std::min(maxGroups, groups - first));
  }
}

}  // namespace

const char* radixRankName(RadixRank rank) {
  return rank == RadixRank::Auto ? "auto" : rank == RadixRank::Ballot ? "ballot" : "partition";
}

RadixRank GpuSorter::resolvedRadixRank(const VulkanContext& ctx, const Tuning& tuning) {
  return tuning.radixRank != RadixRank::Ballot && ctx.info().subgroupPartitioned ? RadixRank::Partition
                                                                                 : RadixRank::Ballot;
}

GpuSorter::GpuSorter(const VulkanContext& ctx, SortAlgorithm algorithm, uint32_t maxCount)
    : GpuSorter(ctx, algorithm, maxCount, Tuning{}) {}

GpuSorter::GpuSorter(const VulkanContext& ctx, SortAlgorithm algorithm, uint32_t maxCount, const Tuning& tuning)
    : ctx_(&ctx), algorithm_(algorithm), maxCount_(maxCount) {
  if (algorithm == SortAlgorithm::Radix || algorithm == SortAlgorithm::OneSweep) {
    const uint32_t subgroup = std::max(1u, ctx.info().subgroupSize);
    const uint32_t kpt = tuning.radixKeysPerThread ? tuning.radixKeysPerThread : kDefaultKeysPerThread;
    if (kpt < 1 || kpt > 32) throw VulkanError("radix sort: keys per thread must be 1..32");
    if (tuning.radixTilesPerGroup < 1 || tuning.radixTilesPerGroup > 64)
      throw VulkanError("radix sort: tiles per work group must be 1..64");
    tilesPerGroup_ = tuning.radixTilesPerGroup;
    if (tuning.radixRank == RadixRank::Partition && (algorithm != SortAlgorithm::Radix || !ctx.info().subgroupPartitioned))
      throw VulkanError("radix sort: ranking by subgroupPartitionNV needs the portable radix passes and a device with "
                        "VK_NV_shader_subgroup_partitioned; " + ctx.info().name + (ctx.info().subgroupPartitioned ? " has it" : " lacks it"));
    rankPartitioned_ = algorithm == SortAlgorithm::Radix && resolvedRadixRank(ctx, tuning) == RadixRank::Partition;
    // The scatter keeps one 256-bin histogram per subgroup; with small subgroups (lavapipe: 8) a 256-wide
    // group would need 32 KiB for them alone, so the group shrinks until everything fits.
    uint32_t group = tuning.radixGroupSize ? tuning.radixGroupSize : SORT_RADIX;
    if (!std::has_single_bit(group) || group > SORT_RADIX || group < subgroup || group % subgroup)
      throw VulkanError("radix sort: group size " + std::to_string(group) +
                        " must be a power of two <= 256 and a multiple of the subgroup size " +
                        std::to_string(subgroup));
    const uint32_t limit = maxSharedBytes(ctx);
    while (scatterSharedBytes(group, kpt, subgroup) > limit) {
      if (tuning.radixGroupSize || group / 2 < subgroup)
        throw VulkanError("radix sort: the scatter does not fit the device's shared memory");
      group /= 2;
    }
    radixTile_ = group * kpt;
    const uint32_t maxGroups = std::max(1u, ceilDiv(maxCount, radixTile_));
    oneSweep_ = algorithm == SortAlgorithm::OneSweep;
    oneSweepSerial_ = oneSweep_ && !oneSweepSupported(ctx);
    if (oneSweep_) {
      oneSweepHistogram_ =
          ComputePipeline(ctx, "sort_onesweep_histogram", sizeof(gpu::SortOneSweepPush), kOneSweepHistogramGroup);
      oneSweepPass_ =
          ComputePipeline(ctx, "sort_onesweep_pass", sizeof(gpu::SortOneSweepPush), group, {{RL_SPEC_SUBGROUP_SIZE, subgroup}, {RL_SPEC_KEYS_PER_THREAD, kpt}});
      oneSweepState_ = GpuBuffer(
          ctx, (VkDeviceSize(SORT_ONESWEEP_STATUS) + VkDeviceSize(SORT_ONESWEEP_MAX_PASSES) * maxGroups * SORT_RADIX) * 4);
    } else {
      histogram_ = ComputePipeline(ctx, "sort_radix_histogram", sizeof(gpu::SortRadixPush), group,
                                   {{RL_SPEC_KEYS_PER_THREAD, kpt}, {RL_SPEC_TILES_PER_GROUP, tilesPerGroup_}});
      scan_ = ComputePipeline(ctx, "sort_radix_scan", sizeof(gpu::SortScanPush), std::max(kScanGroup, subgroup));
      scatter_ = ComputePipeline(ctx, rankPartitioned_ ? "sort_radix_scatter_partitioned" : "sort_radix_scatter",
                                 sizeof(gpu::SortRadixPush), group,
                                 {{RL_SPEC_SUBGROUP_SIZE, subgroup}, {RL_SPEC_KEYS_PER_THREAD, kpt},
                                  {RL_SPEC_TILES_PER_GROUP, tilesPerGroup_}});
      hist_ = GpuBuffer(ctx, (VkDeviceSize(SORT_RADIX) * maxGroups + SORT_RADIX) * 4);
    }
    copy_ = ComputePipeline(ctx, "sort_copy", sizeof(gpu::SortCopyPush), kCopyGroup);
    // Keys, values and input indices of SORT_SMALL_MAX pairs in shared memory (sort_small.comp).
    if (tuning.smallSortMax > 0 && limit >= 3ull * 4 * SORT_SMALL_MAX) {
      smallSortMax_ = std::min<uint32_t>(tuning.smallSortMax, SORT_SMALL_MAX);
      smallSort_ = ComputePipeline(ctx, "sort_small", sizeof(gpu::SortSmallPush), SORT_SMALL_GROUP);
    }
    const VkDeviceSize elementBytes = std::max<VkDeviceSize>(16, VkDeviceSize(maxCount) * 4);
    for (GpuBuffer* b : {&scratchKeys_, &scratchValues_, &secondKeys_, &secondValues_}) *b = GpuBuffer(ctx, elementBytes);
  } else if (algorithm == SortAlgorithm::Bitonic || algorithm == SortAlgorithm::Tile) {
    // No scratch: the padding to a power of two is virtual (see shaders/sort_bitonic.glsl).
    bitonicLocal_ = ComputePipeline(ctx, "sort_bitonic_local", sizeof(gpu::SortBitonicPush), SORT_BITONIC_GROUP);
    bitonicGlobal_ = ComputePipeline(ctx, "sort_bitonic_global", sizeof(gpu::SortBitonicPush), 256);
  }
}

uint64_t GpuSorter::scratchBytes() const {
  uint64_t bytes = 0;
  for (const GpuBuffer* b : {&scratchKeys_, &scratchValues_, &secondKeys_, &secondValues_, &hist_, &oneSweepState_})
    if (b->valid()) bytes += b->size();
  return bytes;
}

bool GpuSorter::oneSweepSupported(const VulkanContext& ctx) {
  // The vendors whose GPUs are documented (CUDA's and ROCm's decoupled look-back scans ship on them) to keep
  // every running work group progressing; CPU implementations run work groups as tasks with no such promise.
  const DeviceInfo& info = ctx.info();
  return !info.isCpu && (info.vendorId == kVendorNvidia || info.vendorId == kVendorAmd);
}

uint32_t GpuSorter::radixPasses(uint32_t keyBits) { return radixPasses(keyBits, 0).passes; }

template <class Record>
void GpuSorter::step(VkCommandBuffer cmd, const char* name, int pass, Record&& record) const {
  if (stepTimer_) stepTimer_->begin(cmd, pass < 0 ? std::string(name) : name + ("/" + std::to_string(pass)));
  record();
  if (stepTimer_) stepTimer_->end(cmd);
}

void GpuSorter::record(VkCommandBuffer cmd, VkDeviceAddress keys, VkDeviceAddress values, uint32_t count,
                       uint32_t keyBits, VkDeviceAddress countLimit, uint32_t ignoredLowBits) {
  if (algorithm_ == SortAlgorithm::None) return;
  if (count > maxCount_)
    throw VulkanError("sort of " + std::to_string(count) + " pairs exceeds the sorter's capacity of " +
                      std::to_string(maxCount_));
  if (keyBits < 1 || keyBits > 32) throw VulkanError("sort: keyBits must be 1..32, got " + std::to_string(keyBits));
  const bool radix = algorithm_ == SortAlgorithm::Radix || algorithm_ == SortAlgorithm::OneSweep;
  if (count > 1) {
    if (radix && count <= smallSortMax_)
      step(cmd, "small", -1, [&] { recordSmall(cmd, keys, values, count, keyBits, countLimit, ignoredLowBits); });
    else if (oneSweep_)
      recordOneSweep(cmd, keys, values, count, keyBits, countLimit, ignoredLowBits);
    else if (radix)
      recordRadix(cmd, keys, values, count, keyBits, countLimit, ignoredLowBits);
    else if (algorithm_ == SortAlgorithm::Tile)
      recordTiles(cmd, keys, values, count, keyBits, countLimit);
    else
      recordBitonic(cmd, keys, values, count, keyBits);
  }
  computeBarrier(cmd);
}

GpuSorter::RadixPasses GpuSorter::radixPasses(uint32_t keyBits, uint32_t ignoredLowBits) {
  const uint32_t sortedBits = keyBits >= 32 ? 32 : keyBits + 1;
  const uint32_t lowBit = std::min(ignoredLowBits, sortedBits - 1);
  return {lowBit, ceilDiv(sortedBits - lowBit, SORT_RADIX_BITS)};
}

void GpuSorter::recordRadix(VkCommandBuffer cmd, VkDeviceAddress keys, VkDeviceAddress values, uint32_t count,
                            uint32_t keyBits, VkDeviceAddress countLimit, uint32_t ignoredLowBits) {
  const auto [lowBit, passes] = radixPasses(keyBits, ignoredLowBits);
  const uint32_t numGroups = ceilDiv(ceilDiv(count, radixTile_), tilesPerGroup_);
  const uint32_t maxGroups = std::max(1u, ctx_->info().maxGroupCountX);
  VkDeviceAddress srcKeys = keys, srcValues = values;
  for (uint32_t pass = 0; pass < passes; ++pass) {
    gpu::SortRadixPush push{};
    push.keysIn = srcKeys;
    push.valuesIn = srcValues;
    std::tie(push.keysOut, push.valuesOut) = passOutput(pass, passes, keys, values);
    push.hist = hist_.address();
    push.count = count;
    push.shift = lowBit + pass * SORT_RADIX_BITS;
    push.keyBits = keyBits;
    push.numGroups = numGroups;
    push.hasCountLimit = countLimit != 0 ? 1 : 0;
    push.countLimit = countLimit;
    const int p = static_cast<int>(pass);
    step(cmd, "histogram", p, [&] { dispatchSplit(histogram_, cmd, push, numGroups, maxGroups); });
    computeBarrier(cmd);
    // CPU devices pay per work group; 4 rows a group still spreads over the cores and keeps each invocation
    // far below lavapipe's cap of 65535 loop iterations per shader invocation.
    const uint32_t rows = ctx_->info().isCpu ? 4 : 1;
    gpu::SortScanPush scanPush{hist_.address(), numGroups, rows};
    step(cmd, "scan", p, [&] { scan_.dispatchGroups(cmd, scanPush, SORT_RADIX / rows); });
    computeBarrier(cmd);
    step(cmd, "scatter", p, [&] { dispatchSplit(scatter_, cmd, push, numGroups, maxGroups); });
    if (pass + 1 < passes) computeBarrier(cmd);
    srcKeys = push.keysOut;
    srcValues = push.valuesOut;
  }
  if (passes == 1) recordCopyBack(cmd, keys, values, count, countLimit);
}

std::pair<VkDeviceAddress, VkDeviceAddress> GpuSorter::passOutput(uint32_t pass, uint32_t passes, VkDeviceAddress keys,
                                                                  VkDeviceAddress values) const {
  if (pass == 0) return {scratchKeys_.address(), scratchValues_.address()};
  if (passes == 3 && pass == 1) return {secondKeys_.address(), secondValues_.address()};
  if (passes == 3 || pass % 2 == 1) return {keys, values};
  return {scratchKeys_.address(), scratchValues_.address()};
}

void GpuSorter::recordSmall(VkCommandBuffer cmd, VkDeviceAddress keys, VkDeviceAddress values, uint32_t count,
                            uint32_t keyBits, VkDeviceAddress countLimit, uint32_t ignoredLowBits) const {
  // The bits the radix passes would order: the same clamp as recordRadix's.
  gpu::SortSmallPush push{keys, values, countLimit, count, keyBits, radixPasses(keyBits, ignoredLowBits).lowBit,
                          countLimit != 0 ? 1u : 0u};
  smallSort_.dispatchGroups(cmd, push, 1);
}

void GpuSorter::recordCopyBack(VkCommandBuffer cmd, VkDeviceAddress keys, VkDeviceAddress values, uint32_t count,
                               VkDeviceAddress countLimit) {
  computeBarrier(cmd);
  gpu::SortCopyPush push{scratchKeys_.address(), scratchValues_.address(), keys, values, count,
                         countLimit != 0 ? 1u : 0u, countLimit};
  const uint32_t maxGroups = std::max(1u, ctx_->info().maxGroupCountX);
  step(cmd, "copy", -1, [&] { copy_.dispatchGroups(cmd, push, std::min(maxGroups, ceilDiv(count, kCopyGroup * 4ull))); });
}

void GpuSorter::recordOneSweep(VkCommandBuffer cmd, VkDeviceAddress keys, VkDeviceAddress values, uint32_t count,
                               uint32_t keyBits, VkDeviceAddress countLimit, uint32_t ignoredLowBits) {
  const auto [lowBit, passes] = radixPasses(keyBits, ignoredLowBits);
  // Tiles cover `count`; with a device-side bound, the tiles past it return at once (after taking their
  // number, so every tile inside the bound still finds its predecessors' counts).
  const uint32_t numTiles = ceilDiv(count, radixTile_);
  const uint32_t maxGroups = std::max(1u, ctx_->info().maxGroupCountX);
  // Zero only what this count uses: histograms, counters and the status words of its tiles.
  const VkDeviceSize stateBytes = (VkDeviceSize(SORT_ONESWEEP_STATUS) + VkDeviceSize(passes) * numTiles * SORT_RADIX) * 4;
  vkCmdFillBuffer(cmd, oneSweepState_.handle(), 0, stateBytes, 0);
  computeBarrier(cmd);
  gpu::SortOneSweepPush push{};
  push.keysIn = keys;
  push.state = oneSweepState_.address();
  push.count = count;
  push.keyBits = keyBits;
  push.numTiles = numTiles;
  push.passes = passes;
  push.shift = lowBit;  // the histogram's digits of pass p start at shift + 8p
  push.hasCountLimit = countLimit != 0 ? 1 : 0;
  push.countLimit = countLimit;
  const uint32_t histChunk = kOneSweepHistogramGroup * SORT_ONESWEEP_HIST_KPT;
  step(cmd, "onesweep-histogram", -1,
       [&] { oneSweepHistogram_.dispatchGroups(cmd, push, std::min(maxGroups, ceilDiv(count, histChunk))); });
  VkDeviceAddress srcKeys = keys, srcValues = values;
  for (uint32_t pass = 0; pass < passes; ++pass) {
    computeBarrier(cmd);
    push.keysIn = srcKeys;
    push.valuesIn = srcValues;
    std::tie(push.keysOut, push.valuesOut) = passOutput(pass, passes, keys, values);
    push.shift = lowBit + pass * SORT_RADIX_BITS;
    push.pass = pass;
    // Tiles come from the pass's counter, not the group id, so a split dispatch needs no offset.
    step(cmd, "onesweep", static_cast<int>(pass), [&] {
      if (oneSweepSerial_) {
        for (uint32_t tile = 0; tile < numTiles; ++tile) {
          if (tile) computeBarrier(cmd);
          oneSweepPass_.dispatchGroups(cmd, push, 1);
        }
      } else {
        for (uint32_t first = 0; first < numTiles; first += maxGroups)
          oneSweepPass_.dispatchGroups(cmd, push, std::min(maxGroups, numTiles - first));
      }
    });
    srcKeys = push.keysOut;
    srcValues = push.valuesOut;
  }
  if (passes == 1) recordCopyBack(cmd, keys, values, count, countLimit);
}

// Each tile of SORT_BITONIC_TILE pairs sorted alone in shared memory: bitonic's first dispatch, no merges.
void GpuSorter::recordTiles(VkCommandBuffer cmd, VkDeviceAddress keys, VkDeviceAddress values, uint32_t count,
                            uint32_t keyBits, VkDeviceAddress countLimit) {
  gpu::SortBitonicPush push{keys, values, count, keyBits};
  push.hasCountLimit = countLimit != 0 ? 1 : 0;
  push.countLimit = countLimit;
  recordLocal(cmd, push, 0);
}

// sort_bitonic_local in `mode` over every tile holding real elements (dispatches split at the group limit).
void GpuSorter::recordLocal(VkCommandBuffer cmd, gpu::SortBitonicPush push, uint32_t mode) const {
  const uint32_t tiles = ceilDiv(push.count, SORT_BITONIC_TILE);
  const uint32_t maxGroups = std::max(1u, ctx_->info().maxGroupCountX);
  push.mode = mode;
  for (uint32_t first = 0; first < tiles; first += maxGroups) {
    push.tileOffset = first;
    bitonicLocal_.dispatchGroups(cmd, push, std::min(maxGroups, tiles - first));
  }
}

void GpuSorter::recordBitonic(VkCommandBuffer cmd, VkDeviceAddress keys, VkDeviceAddress values, uint32_t count,
                              uint32_t keyBits) {
  const uint32_t paddedLog = static_cast<uint32_t>(std::bit_width(count - 1u));  // 2^paddedLog >= count
  const uint32_t maxGroups = std::max(1u, ctx_->info().maxGroupCountX);
  gpu::SortBitonicPush push{keys, values, count, keyBits};
  recordLocal(cmd, push, 0);
  // Merges of blocks larger than a tile: the steps that cross tiles one dispatch each, then the rest in
  // shared memory.
  for (uint32_t blockLog = SORT_BITONIC_TILE_LOG + 1; blockLog <= paddedLog; ++blockLog) {
    push.comparators = uint32_t(1) << (paddedLog - 1);
    const uint32_t groups = std::min(maxGroups, ceilDiv(push.comparators, bitonicGlobal_.groupSize()));
    computeBarrier(cmd);
    push.mode = 0;
    push.blockLog = blockLog;
    bitonicGlobal_.dispatchGroups(cmd, push, groups);
    for (uint32_t distanceLog = blockLog - 2; distanceLog >= SORT_BITONIC_TILE_LOG; --distanceLog) {
      computeBarrier(cmd);
      push.mode = 1;
      push.distanceLog = distanceLog;
      bitonicGlobal_.dispatchGroups(cmd, push, groups);
    }
    computeBarrier(cmd);
    recordLocal(cmd, push, 1);
  }
}

}  // namespace raylab
