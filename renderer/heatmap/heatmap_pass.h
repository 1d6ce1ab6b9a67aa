// The heatmap views (Settings::heatmap): per pixel, a quantity of the path traced there at one bounce
// (sort key, predicted-vs-actual cell, traversal steps, warp efficiency, length-cache mean or variance),
// drawn instead of the render, with what the legend and the hover readout need (FrameStats::heatmap).
#pragma once

#include <optional>
#include <vector>

#include <vulkan/vulkan.h>

#include "renderer/frame_stats.h"
#include "renderer/heatmap/heatmap_colours.h"
#include "renderer/settings/settings.h"
#include "renderer/vk/lazy_pipeline.h"
#include "renderer/vk/gpu_buffer.h"

namespace raylab {

class VulkanContext;
class StageTimer;
struct PathBuffers;

class HeatmapPass {
 public:
  HeatmapPass(const VulkanContext& ctx, uint32_t pixelCount);

  // The frame loop's calls: which view is shown and at which bounce is decided here (heatmap_rules.h: an
  // unavailable view is never gathered). configure() takes the view, the bounce and the colouring from the
  // settings when the frame's steps are made (the steps ask readsAfterTrace/readsAfterSort), and
  // recordClear() clears when the frame starts on the GPU. keyParams: KeyStage::paramsAddress() while
  // sorting, else 0, with its grid (nullptr without); hasCache: the key stage holds a length cache (a
  // second guard: the cache views read it only then).
  void configure(const Settings& settings, VkDeviceAddress keyParams, const gpu::GpuKeyGrid* grid, bool hasCache);
  void recordClear(VkCommandBuffer cmd);
  // After the trace of `bounce` (the trace's own views, cell hits and the cache views).
  // Whether afterTrace of `bounce` reads the trace's hits and steps (so trace and shade must stay apart).
  bool readsAfterTrace(uint32_t bounce) const;
  void afterTrace(VkCommandBuffer cmd, const PathBuffers& buffers, uint32_t stateSet, uint32_t bounce,
                  StageTimer* timer);
  // After the keys made during `bounce` for the rays of bounce + 1 (sort keys).
  void afterKeys(VkCommandBuffer cmd, const PathBuffers& buffers, uint32_t stateSet, uint32_t bounce,
                 StageTimer* timer);
  // After those keys were sorted into `sortedSet` (sort keys coloured by rank: slot order is key order).
  // Whether afterSort of `bounce` reads anything (the sort-key rank view of the next bounce).
  bool readsAfterSort(uint32_t bounce) const;
  void afterSort(VkCommandBuffer cmd, const PathBuffers& buffers, uint32_t sortedSet, uint32_t bounce,
                 StageTimer* timer);
  void afterMegakernel(VkCommandBuffer cmd, const PathBuffers& buffers, StageTimer* timer);
  // Writes the colours into the display image and copies the probed pixel's data for the host; returns
  // false when no view is shown (the caller tonemaps instead).
  bool colorize(VkCommandBuffer cmd, const PathBuffers& buffers, StageTimer* timer);
  // After the frame completed: range, unit, pixel counts and the probe into stats.heatmap.
  void finishFrame(FrameStats& stats);

  // The pixel whose data the next frames read back (one 16-byte copy a frame), or none. The window sets it
  // while the mouse is over the image.
  void setProbe(std::optional<glm::uvec2> pixel) { probe_ = pixel; }

  // Tests and tools: the per-pixel heat words (values or RL_HEAT_* sentinels) of the last frame, and how
  // heatmap_colorize.comp coloured them (the range it used is the last finished frame's).
  std::vector<uint32_t> readValues() const;
  // ... and their probe words (RL_HEAT_PROBE_STRIDE a pixel: path id, key, cell, octant).
  std::vector<uint32_t> readProbes() const;
  const HeatmapColouring& colouring() const { return colouring_; }

 private:
  void gather(VkCommandBuffer cmd, const PathBuffers& buffers, uint32_t stateSet, uint32_t gatherKind,
              bool megakernel, StageTimer* timer);
  gpu::HeatmapPush push(const PathBuffers& buffers, uint32_t stateSet, uint32_t gatherKind, bool megakernel) const;

  LazyPipeline gather_, colorize_;  // built when a heatmap is first drawn
  uint32_t pixelCount_;
  GpuBuffer heat_, probeData_, range_, probeReadback_;
  HeatmapView view_ = HeatmapView::None;
  uint32_t bounce_ = 0;
  uint32_t width_ = 0;
  VkDeviceAddress keyParams_ = 0;
  bool hasCache_ = false;
  bool gathered_ = false;  // a gather was recorded this frame (auto sort policy: no keys, no sort-key data)
  bool rangeFixed_ = false;
  HeatmapColouring colouring_;
  std::optional<glm::uvec2> probe_;
  std::optional<glm::uvec2> probeRecorded_;  // the pixel whose copy the frame being recorded holds
};

}  // namespace raylab
