// A frame's detailed statistics on the GPU: the detail passes (shaders/detail_types.h) recorded where a
// whole frame has the arrays they read (after a trace, after the keys, at the end of the frame), each timed
// as the "counters" stage (StageRole::Instrument: outside the frame's work and the sort policy's inputs),
// and one small copy of their sums for the host. The host never reads a per-path array, so a detailed
// frame costs the GPU a few reads of its arrays and the host a few kilobytes.
#pragma once

#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

#include "renderer/vk/compute_pipeline.h"
#include "renderer/vk/gpu_buffer.h"
#include "renderer/vk/lazy_pipeline.h"
#include "shaders/detail_types.h"

namespace raylab {

class StageTimer;
class VulkanContext;

class DetailStats {
 public:
  explicit DetailStats(const VulkanContext& ctx);

  // The frame's first detail command: zero sums for `bounces` bounces, forget which passes ran.
  void recordClear(VkCommandBuffer cmd, uint32_t bounces);
  // Warp efficiency of a trace's `count` slots of traversal steps (`steps`: GpuHits::steps).
  void recordWarps(VkCommandBuffer cmd, VkDeviceAddress steps, uint32_t count, uint32_t bounce, StageTimer* timer);
  // Prediction figures of bounce `bounce`'s rays (state set `stateSet` of the frame block) after its trace.
  void recordPrediction(VkCommandBuffer cmd, VkDeviceAddress frameBlock, VkDeviceAddress keyParams, uint32_t stateSet,
                        uint32_t count, float invDiagonal, uint32_t bounce, StageTimer* timer);
  // Distinct live keys among `count` keys made for bounce `bounce`'s rays; `liveBits`: KeyStage::keyBits() - 1.
  void recordDistinctKeys(VkCommandBuffer cmd, VkDeviceAddress keys, uint32_t count, uint32_t liveBits,
                          uint32_t bounce, StageTimer* timer);
  // Length-cache entries holding samples (into bounce 0's sums).
  void recordCacheUsed(VkCommandBuffer cmd, VkDeviceAddress keyParams, uint32_t entryCount, StageTimer* timer);
  // The sums to the host-visible copy; the caller's barrier to the host follows.
  void recordToHost(VkCommandBuffer cmd) const;

  // After the frame's fence: a bounce's sums, and which of its passes ran this frame.
  const gpu::GpuDetailSums& sums(uint32_t bounce) const;
  bool measuredWarps(uint32_t bounce) const { return bounce < ran_.size() && ran_[bounce].warps; }
  bool measuredPrediction(uint32_t bounce) const {
    return bounce < ran_.size() && ran_[bounce].prediction && ran_[bounce].keys;
  }
  bool measuredCache() const { return cacheRan_; }

 private:
  gpu::DetailPush pushFor(uint32_t bounce) const;
  void ensureBitmap(uint32_t liveBits);

  const VulkanContext& ctx_;
  LazyPipeline warps_, prediction_, keys_, cache_;
  GpuBuffer sums_, hostSums_, bitmap_;
  std::vector<GpuBuffer> retired_;  // bitmaps outgrown during the frame being recorded
  struct Ran {
    bool warps = false, prediction = false, keys = false;
  };
  std::vector<Ran> ran_;
  bool cacheRan_ = false;
};

}  // namespace raylab
