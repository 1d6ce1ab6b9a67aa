// Sorting (key, value) uint32 pairs on the GPU, in place in the caller's buffers, by the low `keyBits` bits of
// the key: the step between computing the rays' sort keys and reordering the path state.
//
// Keys: the caller guarantees key < 2^keyBits or key == 0xFFFFFFFF (a dead path, RL_DEAD_KEY). Dead keys sort
// after every live key: the sort compares min(key, 2^keyBits), i.e. it sorts keyBits + 1 bits (when keyBits
// < 32), so a dead key never ties with the largest live key. Any other key >= 2^keyBits sorts as a dead one.
//
// Radix (the default): LSD, stable, 8-bit digits, reduce-then-scan with no work group ever waiting on
// another (so it runs on CPU devices like lavapipe that give no forward progress between groups). Each pass
// is three dispatches: per-tile digit histograms, a scan of those per digit, and a stable scatter ranked by
// subgroup ballots. Only ceil((keyBits + 1) / 8) passes run (4 for the lab's 30-bit Morton keys).
// OneSweep (SortAlgorithm::OneSweep): the radix sort's order and tile ranking, but one dispatch per pass using
// decoupled look-back (plus one histogram dispatch for all passes, after a fill of its state). Work groups
// wait on earlier ones, which only devices known to give forward progress promise (NVIDIA and AMD GPUs);
// elsewhere (CPU devices) each pass runs one work group per dispatch, a barrier between: the same order
// from the same shaders, so the invariant tests check them on lavapipe, but slow (oneSweepSerial()).
// Both radix sorts end in the caller's buffers without copying every pair back after an odd pass count:
// three passes (17 to 24 sorted bits, the two-point keys) rotate through a second scratch set (passOutput);
// only a single pass is copied back. That costs 8 bytes a pair of memory and saves a dispatch, a barrier and
// 16 bytes a pair read and written per sort.
// Small counts (radix and OneSweep, at most Tuning::smallSortMax pairs, SORT_SMALL_MAX by default): one
// dispatch, one work group sorting them all in shared memory (sort_small.comp), stable like the radix passes
// it replaces, which at such counts cost their launches and barriers, not their bytes (issue 36).
// Bitonic (the study's baseline): any count, padded virtually to a power of two; steps whose distance fits a
// 2048-element tile run in shared memory, the others as one dispatch per step. Not stable.
// Tile: bitonic's first dispatch alone: each 2048-element tile sorted on its own, so the result is sorted only
// within tiles. Not stable. Honours countLimit (tiles past it return at once).
//
// The caller makes the keys and values visible to compute shaders before record() (computeBarrier).
#pragma once

#include <cstdint>
#include <utility>

#include <vulkan/vulkan.h>

#include "renderer/vk/compute_pipeline.h"
#include "renderer/vk/gpu_buffer.h"
#include "renderer/settings/settings.h"
#include "shaders/sort_types.h"

namespace raylab {

// The default of GpuSorter::Tuning::radixTilesPerGroup (its comment says why 2).
inline constexpr uint32_t kDefaultRadixTilesPerGroup = 2;

// How the portable radix scatter finds the lanes of a subgroup holding the same digit: a ballot per digit bit
// (any device), or one subgroupPartitionNV (devices with VK_NV_shader_subgroup_partitioned: NVIDIA). Auto: the
// partition where the device has it, else the ballots.
enum class RadixRank { Auto, Ballot, Partition };
inline constexpr RadixRank kRadixRanks[] = {RadixRank::Auto, RadixRank::Ballot, RadixRank::Partition};
// The default of GpuSorter::Tuning::radixRank: the ballots. On an H100 (docs/results/partition-rank) the
// partition made the sort of uniform 23-bit keys 12-14% slower (0.9M-8.4M pairs; its scatter 0.497 against
// 0.427 ms at 8.4M) and of few-valued keys 4-5% faster; the frame's three sorts took 1-4% longer.
inline constexpr RadixRank kDefaultRadixRank = RadixRank::Ballot;
// "auto", "ballot" or "partition" (sortbench --radix-rank).
const char* radixRankName(RadixRank rank);

class StageTimer;
class VulkanContext;

class GpuSorter {
 public:
  // Radix scatter shape; 0 picks the device default. For tuning runs (sortbench --radix-group/--radix-kpt/
  // --radix-tiles).
  struct Tuning {
    uint32_t radixGroupSize = 0;      // power of two, 16..256, a multiple of the subgroup size
    uint32_t radixKeysPerThread = 0;  // 1..32
    // Consecutive tiles one work group of the portable radix passes counts and scatters (1..64): fewer
    // columns in the count table and fewer scattered reads and writes of it, fewer groups in flight. 2: on an
    // H100 the frame's three sorts took 4-12% less than with 1 (Sponza at 720p 1% more) and sortbench's
    // 2-10% less from 0.9M to 8.4M pairs; 4 lost at 0.9M (docs/results/sortbench-back-to-back).
    uint32_t radixTilesPerGroup = kDefaultRadixTilesPerGroup;
    // How the portable radix scatter ranks a tile's keys (RadixRank). Partition needs
    // DeviceInfo::subgroupPartitioned (NVIDIA; not lavapipe); the constructor refuses it elsewhere.
    RadixRank radixRank = kDefaultRadixRank;
    // Radix counts up to this many pairs take the single-dispatch small sort; 0: never (the passes always run).
    uint32_t smallSortMax = SORT_SMALL_MAX;
  };

  // The ranking the portable radix passes take on this device under `tuning`: Auto resolved to Partition or
  // Ballot (Partition where the device lacks it is refused by the constructor, not here).
  static RadixRank resolvedRadixRank(const VulkanContext& ctx, const Tuning& tuning);
  // Whether OneSweep's work groups may run together on this device (a GPU known to give forward progress).
  static bool oneSweepSupported(const VulkanContext& ctx);

  GpuSorter(const VulkanContext& ctx, SortAlgorithm algorithm, uint32_t maxCount);
  GpuSorter(const VulkanContext& ctx, SortAlgorithm algorithm, uint32_t maxCount, const Tuning& tuning);

  // Records commands that sort `count` (key, value) pairs held in the device buffers at addresses `keys` and
  // `values` (each at least count elements) by the low `keyBits` bits (1..32) of the key, in place, and a
  // barrier at the end so later stages may read the result. Radix: stable. Bitonic: keys sorted, values
  // carried with their keys. count <= maxCount. SortAlgorithm::None records nothing.
  // `countLimit` (optional): the device address of a uint32 bound the device knows and the host does not
  // (the live-path count after the last sort): the radix sorts (portable, OneSweep, small) then sort only the
  // first min(count, *countLimit) pairs and leave the rest where they are; their dispatches keep their sizes,
  // and work groups past the bound return at once. Bitonic ignores it and sorts all `count` pairs, which gives
  // the same keys when the pairs past the bound are dead; Tile honours it too (whole tiles past it).
  // `ignoredLowBits` (the radix sorts): the lowest bits of the compared key are not ordered (pairs that
  // differ only there keep their input order), one pass less for each 8 bits: a coarser, cheaper order.
  void record(VkCommandBuffer cmd, VkDeviceAddress keys, VkDeviceAddress values, uint32_t count, uint32_t keyBits,
              VkDeviceAddress countLimit = 0, uint32_t ignoredLowBits = 0);

  // Times each dispatch record() records as a scope of `timer`, named by its step: "histogram/P", "scan/P" and
  // "scatter/P" for radix pass P, "onesweep-histogram" and "onesweep/P", "small", "copy" (sortbench --steps,
  // which finds where a sort's time goes). nullptr, the default, records no scopes.
  void timeSteps(StageTimer* timer) { stepTimer_ = timer; }
  SortAlgorithm algorithm() const { return algorithm_; }
  uint64_t scratchBytes() const;  // memory the sorter owns (for the stats)
  uint32_t maxCount() const { return maxCount_; }

  // Radix passes run for `keyBits` (one extra bit for dead keys below 32 bits).
  static uint32_t radixPasses(uint32_t keyBits);
  // The radix sorts' passes for `keyBits` with `ignoredLowBits` not ordered: the lowest ordered bit (the
  // ignored bits, clamped below the sorted ones) and the 8-bit passes from it to the top.
  struct RadixPasses {
    uint32_t lowBit;
    uint32_t passes;
  };
  static RadixPasses radixPasses(uint32_t keyBits, uint32_t ignoredLowBits);
  // Elements per radix tile (scatter group size times keys per invocation) on this device.
  uint32_t radixTile() const { return radixTile_; }
  // True when record() runs OneSweep passes (SortAlgorithm::OneSweep), and when it runs them one work group
  // per dispatch because the device may not run work groups together (see oneSweepSupported).
  bool usesOneSweep() const { return oneSweep_; }
  // True when the portable radix scatter ranks with subgroupPartitionNV (Tuning::radixRank, resolved).
  bool ranksPartitioned() const { return rankPartitioned_; }
  bool oneSweepSerial() const { return oneSweepSerial_; }
  // The most pairs record() sorts with the single-dispatch small sort (0: none; radix only, and where the
  // device's shared memory holds its arrays).
  uint32_t smallSortMax() const { return smallSortMax_; }

 private:
  void recordRadix(VkCommandBuffer cmd, VkDeviceAddress keys, VkDeviceAddress values, uint32_t count,
                   uint32_t keyBits, VkDeviceAddress countLimit, uint32_t ignoredLowBits);
  // Where radix pass `pass` of `passes` writes (keys, values): an even count ping-pongs caller -> scratch ->
  // caller; three passes go caller -> scratch -> second -> caller; one pass ends in scratch (recordCopyBack).
  std::pair<VkDeviceAddress, VkDeviceAddress> passOutput(uint32_t pass, uint32_t passes, VkDeviceAddress keys,
                                                         VkDeviceAddress values) const;
  // After a single radix pass the result is in scratch: copy it to the caller's buffers.
  void recordCopyBack(VkCommandBuffer cmd, VkDeviceAddress keys, VkDeviceAddress values, uint32_t count,
                      VkDeviceAddress countLimit);
  void recordOneSweep(VkCommandBuffer cmd, VkDeviceAddress keys, VkDeviceAddress values, uint32_t count,
                      uint32_t keyBits, VkDeviceAddress countLimit, uint32_t ignoredLowBits);
  void recordBitonic(VkCommandBuffer cmd, VkDeviceAddress keys, VkDeviceAddress values, uint32_t count,
                     uint32_t keyBits);
  void recordTiles(VkCommandBuffer cmd, VkDeviceAddress keys, VkDeviceAddress values, uint32_t count,
                   uint32_t keyBits, VkDeviceAddress countLimit);
  void recordLocal(VkCommandBuffer cmd, gpu::SortBitonicPush push, uint32_t mode) const;
  void recordSmall(VkCommandBuffer cmd, VkDeviceAddress keys, VkDeviceAddress values, uint32_t count,
                   uint32_t keyBits, VkDeviceAddress countLimit, uint32_t ignoredLowBits) const;
  // record() inside a step scope of stepTimer_ (when set); `pass` < 0: a step of no pass.
  template <class Record>
  void step(VkCommandBuffer cmd, const char* name, int pass, Record&& record) const;

  const VulkanContext* ctx_ = nullptr;
  SortAlgorithm algorithm_ = SortAlgorithm::None;
  uint32_t maxCount_ = 0;
  uint32_t radixTile_ = 0;
  uint32_t tilesPerGroup_ = 1;
  bool oneSweep_ = false;
  bool rankPartitioned_ = false;
  bool oneSweepSerial_ = false;
  uint32_t smallSortMax_ = 0;
  StageTimer* stepTimer_ = nullptr;

  // Radix
  ComputePipeline histogram_;
  ComputePipeline scan_;
  ComputePipeline scatter_;
  ComputePipeline copy_;
  GpuBuffer scratchKeys_;
  GpuBuffer scratchValues_;
  GpuBuffer hist_;  // per-tile digit counts (digit-major), then the digit totals

  // OneSweep
  ComputePipeline oneSweepHistogram_;
  ComputePipeline oneSweepPass_;
  GpuBuffer oneSweepState_;  // histograms, tile counters, look-back status (shaders/sort_types.h)
  GpuBuffer secondKeys_;     // the second scratch set three passes rotate through (passOutput)
  GpuBuffer secondValues_;

  // Small counts
  ComputePipeline smallSort_;

  // Bitonic
  ComputePipeline bitonicLocal_;
  ComputePipeline bitonicGlobal_;
};

}  // namespace raylab
