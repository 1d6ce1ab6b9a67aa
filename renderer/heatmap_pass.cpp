#include "renderer/heatmap_pass.h"

#include <algorithm>
#include <cstring>

#include "renderer/heatmap_rules.h"
#include "renderer/path_buffers.h"
#include "renderer/vk/stage_timer.h"
#include "renderer/vk/vk_context.h"
#include "shaders/heatmap_types.h"

namespace raylab {

static_assert(static_cast<uint32_t>(HeatmapView::SortKey) == RL_HEAT_SORT_KEY);
static_assert(static_cast<uint32_t>(HeatmapView::CacheVariance) == RL_HEAT_CACHE_VARIANCE);

HeatmapPass::HeatmapPass(const VulkanContext& ctx, uint32_t pixelCount)
    : gather_(ctx, "heatmap_gather", sizeof(gpu::HeatmapPush), RL_PATH_GROUP_SIZE),
      colorize_(ctx, "heatmap_colorize", sizeof(gpu::HeatmapPush), RL_PATH_GROUP_SIZE),
      heat_(ctx, VkDeviceSize(pixelCount) * 4),
      range_(ctx, 4 * 4, MemoryKind::HostVisible) {}

void HeatmapPass::beginFrame(VkCommandBuffer cmd, const Settings& settings, bool hasCache) {
  view_ = heatmapShown(settings);
  bounce_ = heatmapBounceShown(settings);
  hasCache_ = hasCache;
  if (view_ != HeatmapView::None) recordClear(cmd);
}

void HeatmapPass::afterTrace(VkCommandBuffer cmd, const PathBuffers& buffers, uint32_t stateSet, uint32_t bounce,
                             VkDeviceAddress keyParams, StageTimer* timer) const {
  if (view_ != HeatmapView::None && view_ != HeatmapView::SortKey && bounce == bounce_)
    recordGather(cmd, view_, buffers, stateSet, keyParams, hasCache_, false, timer);
}

void HeatmapPass::afterKeys(VkCommandBuffer cmd, const PathBuffers& buffers, uint32_t stateSet, uint32_t bounce,
                            VkDeviceAddress keyParams, StageTimer* timer) const {
  if (view_ == HeatmapView::SortKey && bounce + 1 == bounce_)
    recordGather(cmd, view_, buffers, stateSet, keyParams, hasCache_, false, timer);
}

void HeatmapPass::afterMegakernel(VkCommandBuffer cmd, const PathBuffers& buffers, StageTimer* timer) const {
  // Only per-path totals exist after a megakernel: the whole path's traversal steps.
  if (view_ == HeatmapView::TraversalSteps || view_ == HeatmapView::WarpEfficiency)
    recordGather(cmd, view_, buffers, 0, 0, false, true, timer);
}

bool HeatmapPass::colorize(VkCommandBuffer cmd, const PathBuffers& buffers, StageTimer* timer) const {
  if (view_ == HeatmapView::None) return false;
  recordColorize(cmd, view_, buffers, timer);
  return true;
}

void HeatmapPass::finishFrame(FrameStats& stats) const {
  if (view_ != HeatmapView::None) readRange(view_, stats);
}

void HeatmapPass::recordClear(VkCommandBuffer cmd) const {
  heat_.recordFill(cmd, RL_HEAT_EMPTY);
  vkCmdFillBuffer(cmd, range_.handle(), 0, 4, 0x7F7FFFFFu);  // min starts at the largest float
  vkCmdFillBuffer(cmd, range_.handle(), 4, 4, 0u);
  computeBarrier(cmd);
}

void HeatmapPass::recordGather(VkCommandBuffer cmd, HeatmapView view, const PathBuffers& buffers,
                               uint32_t stateSet, VkDeviceAddress keyParams, bool hasCache, bool megakernel,
                               StageTimer* timer) const {
  ScopedStage s(timer, cmd, "heatmap");
  gpu::HeatmapPush push{buffers.frameBlock.address(), keyParams, buffers.keys.address(), heat_.address(),
                        range_.address(), static_cast<uint32_t>(view), stateSet, megakernel ? 1u : 0u,
                        keyParams != 0 ? 1u : 0u, keyParams != 0 && hasCache ? 1u : 0u};
  gather_.dispatchThreads(cmd, push, buffers.pathCount);
  computeBarrier(cmd);
}

void HeatmapPass::recordColorize(VkCommandBuffer cmd, HeatmapView view, const PathBuffers& buffers,
                                 StageTimer* timer) const {
  ScopedStage s(timer, cmd, "heatmap");
  gpu::HeatmapPush push{buffers.frameBlock.address(), 0, buffers.keys.address(), heat_.address(),
                        range_.address(), static_cast<uint32_t>(view), 0, 0, 0, 0};
  colorize_.dispatchThreads(cmd, push, buffers.pixelCount);
  computeBarrier(cmd);
}

void HeatmapPass::readRange(HeatmapView view, FrameStats& stats) const {
  const auto* r = static_cast<const uint32_t*>(range_.mapped());
  if (r[0] > r[1]) {  // nothing written this frame
    stats.heatmapMin = stats.heatmapMax = 0.0;
  } else if (view == HeatmapView::SortKey) {
    stats.heatmapMin = r[0];
    stats.heatmapMax = r[1];
  } else {
    float lo, hi;
    std::memcpy(&lo, &r[0], 4);
    std::memcpy(&hi, &r[1], 4);
    stats.heatmapMin = lo;
    stats.heatmapMax = hi;
  }
  switch (view) {
    case HeatmapView::SortKey: stats.heatmapUnit = "sort key"; break;
    case HeatmapView::CellHit: stats.heatmapUnit = "estimated cell = actual cell"; break;
    case HeatmapView::TraversalSteps: stats.heatmapUnit = "traversal steps"; break;
    case HeatmapView::WarpEfficiency: stats.heatmapUnit = "warp efficiency (W=32)"; break;
    case HeatmapView::CacheMean: stats.heatmapUnit = "cached length mean"; break;
    case HeatmapView::CacheVariance: stats.heatmapUnit = "cached length variance"; break;
    default: stats.heatmapUnit.clear();
  }
}

}  // namespace raylab
