// The heatmap views (Settings::heatmap): per pixel, a quantity of the path traced there at one bounce
// (sort key, predicted-vs-actual cell, traversal steps, warp efficiency, length-cache mean or variance),
// drawn instead of the render, with the value range reported for the legend.
#pragma once

#include <vulkan/vulkan.h>

#include "renderer/vk/compute_pipeline.h"
#include "renderer/frame_stats.h"
#include "renderer/vk/gpu_buffer.h"
#include "renderer/settings.h"

namespace raylab {

class VulkanContext;
class StageTimer;
struct PathBuffers;

class HeatmapPass {
 public:
  HeatmapPass(const VulkanContext& ctx, uint32_t pixelCount);

  // The frame loop's calls: which view is shown and at which bounce is decided here. beginFrame() takes
  // the view and the bounce (Settings::heatmapBounce within the frame's bounces) and clears; the after*
  // calls gather only where that view and bounce are; colorize() returns false when no view is shown (the
  // caller tonemaps instead). keyParams: KeyStage::paramsAddress() while sorting, else 0.
  // The view and bounce are heatmap_rules.h's (an unavailable view is never gathered); hasCache: the key
  // stage holds a length cache (a second guard: the cache views read it only then).
  void beginFrame(VkCommandBuffer cmd, const Settings& settings, bool hasCache);
  void afterTrace(VkCommandBuffer cmd, const PathBuffers& buffers, uint32_t stateSet, uint32_t bounce,
                  VkDeviceAddress keyParams, StageTimer* timer) const;
  // After the keys made during `bounce` for the rays of bounce + 1.
  void afterKeys(VkCommandBuffer cmd, const PathBuffers& buffers, uint32_t stateSet, uint32_t bounce,
                 VkDeviceAddress keyParams, StageTimer* timer) const;
  void afterMegakernel(VkCommandBuffer cmd, const PathBuffers& buffers, StageTimer* timer) const;
  bool colorize(VkCommandBuffer cmd, const PathBuffers& buffers, StageTimer* timer) const;
  void finishFrame(FrameStats& stats) const;

  // Clears the per-pixel values and the range; call at the start of a frame that shows a heatmap.
  void recordClear(VkCommandBuffer cmd) const;
  // Gathers the view's value from the paths of the current set (after the trace, or the key stage for
  // SortKey). keyParams: KeyStage::paramsAddress(), or 0 without a key stage; hasCache: the key stage
  // holds a length cache (its addresses in keyParams are zero otherwise and must not be read).
  void recordGather(VkCommandBuffer cmd, HeatmapView view, const PathBuffers& buffers, uint32_t stateSet,
                    VkDeviceAddress keyParams, bool hasCache, bool megakernel, StageTimer* timer) const;
  // Writes the colours into the display image (instead of the tonemap).
  void recordColorize(VkCommandBuffer cmd, HeatmapView view, const PathBuffers& buffers, StageTimer* timer) const;
  // After the frame completed: the legend's value range and unit.
  void readRange(HeatmapView view, FrameStats& stats) const;

 private:
  ComputePipeline gather_, colorize_;
  GpuBuffer heat_, range_;
  HeatmapView view_ = HeatmapView::None;
  uint32_t bounce_ = 0;
  bool hasCache_ = false;
};

}  // namespace raylab
