#include "renderer/path_tracer.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "renderer/frame_reorder.h"
#include "renderer/heatmap_pass.h"
#include "renderer/heatmap_rules.h"
#include "renderer/vk_check.h"
#include "renderer/vk_context.h"
#include "renderer/warp_efficiency.h"

namespace raylab {
namespace {

constexpr uint32_t kGroup = RL_PATH_GROUP_SIZE;

}  // namespace

gpu::GpuCamera makeGpuCamera(const Viewpoint& v, uint32_t width, uint32_t height) {
  gpu::GpuCamera c{};
  glm::vec3 forward = v.target - v.position;
  if (glm::length(forward) < 1e-12f) forward = glm::vec3(0.0f, 0.0f, -1.0f);
  forward = glm::normalize(forward);
  glm::vec3 up = glm::length(v.up) > 0.0f ? glm::normalize(v.up) : glm::vec3(0.0f, 1.0f, 0.0f);
  glm::vec3 right = glm::cross(forward, up);
  if (glm::length(right) < 1e-6f) right = glm::cross(forward, std::abs(forward.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0));
  right = glm::normalize(right);
  c.position = v.position;
  c.forward = forward;
  c.right = right;
  c.up = glm::cross(right, forward);
  c.tanHalfFovY = std::tan(0.5f * v.yfovRadians);
  c.aspect = static_cast<float>(width) / static_cast<float>(height);
  return c;
}

PathTracer::PathTracer(const VulkanContext& ctx, const Scene& scene, const Settings& settings, const Viewpoint& camera)
    : ctx_(ctx),
      settings_(settings),
      camera_(camera),
      scene_(std::make_unique<GpuSceneData>(ctx, scene)),
      generate_(ctx, "generate", sizeof(gpu::PathStagePush), kGroup),
      trace_(ctx, "trace", sizeof(gpu::PathStagePush), kGroup, {0}),
      traceCounting_(ctx, "trace", sizeof(gpu::PathStagePush), kGroup, {1}),
      shade_(ctx, "shade", sizeof(gpu::PathStagePush), kGroup),
      accumulate_(ctx, "accumulate", sizeof(gpu::PathStagePush), kGroup),
      tonemap_(ctx, "tonemap", sizeof(gpu::PathStagePush), kGroup),
      megakernel_(ctx, "megakernel", sizeof(gpu::PathStagePush), kGroup, {0}),
      megakernelCounting_(ctx, "megakernel", sizeof(gpu::PathStagePush), kGroup, {1}),
      timer_(ctx) {
  reorder_ = std::make_unique<FrameReorder>(ctx, scene, settings_, camera_.position,
                                            settings_.width * settings_.height * settings_.sppPerFrame);
  allocate();
}

PathTracer::~PathTracer() { vkDeviceWaitIdle(ctx_.device()); }

void PathTracer::allocate() {
  buffers_.reset();
  buffers_ = std::make_unique<PathBuffers>(ctx_, settings_.width, settings_.height, settings_.sppPerFrame,
                                           settings_.bounces);
  reorder_->resize(buffers_->pathCount);
  heatmap_ = std::make_unique<HeatmapPass>(ctx_, buffers_->pixelCount);
  resetAccumulation();
}

void PathTracer::resetAccumulation() {
  frameIndex_ = 0;
  ctx_.submitAndWait([&](VkCommandBuffer cmd) { buffers_->accumulation.recordFill(cmd, 0); });
}

void PathTracer::applySettings(const Settings& next) {
  Settings previous = settings_;
  settings_ = next;
  bool resized = next.width != previous.width || next.height != previous.height ||
                 next.sppPerFrame != previous.sppPerFrame || next.bounces != previous.bounces;
  reorder_->configure(settings_, camera_.position);
  if (resized)
    allocate();
  else if (next.requiresAccumulationReset(previous))
    resetAccumulation();
}

void PathTracer::setCamera(const Viewpoint& camera) {
  camera_ = camera;
  reorder_->configure(settings_, camera_.position);
  resetAccumulation();
}

void PathTracer::recordFrame(VkCommandBuffer cmd) {
  timer_.reset(cmd);
  gpu::GpuFrame frame = buffers_->addresses();
  frame.camera = makeGpuCamera(camera_, settings_.width, settings_.height);
  frame.scene = scene_->block();
  frame.width = settings_.width;
  frame.height = settings_.height;
  frame.sppPerFrame = settings_.sppPerFrame;
  frame.frameIndex = frameIndex_;
  frame.bounceCount = settings_.bounces;
  frame.seed = settings_.seed;
  frame.exposure = settings_.exposure;
  // An unavailable view (heatmap_rules.h) is never gathered: its data would come from a stage not running.
  const HeatmapView view = heatmapShown(settings_);
  {
    // Every command of the frame is inside a timed scope, so the stages account for the frame's GPU time.
    ScopedStage s(&timer_, cmd, "setup");
    vkCmdUpdateBuffer(cmd, buffers_->frameBlock.handle(), 0, sizeof(frame), &frame);
    buffers_->counters.recordFill(cmd, 0);
    computeBarrier(cmd);
    if (view != HeatmapView::None) heatmap_->recordClear(cmd);
  }

  gpu::PathStagePush push{buffers_->frameBlock.address(), 0, 0, settings_.countSimt ? 1u : 0u, 0};
  if (settings_.kernel == Kernel::Megakernel) {
    ScopedStage s(&timer_, cmd, "megakernel");
    (settings_.countSimt ? megakernelCounting_ : megakernel_).dispatchThreads(cmd, push, buffers_->pathCount);
    computeBarrier(cmd);
    recordTraceCounters(cmd, 0);
    if (view == HeatmapView::TraversalSteps || view == HeatmapView::WarpEfficiency)
      heatmap_->recordGather(cmd, view, *buffers_, 0, 0, false, true, &timer_);
  } else {
    recordWavefront(cmd, push);
  }
  {
    ScopedStage s(&timer_, cmd, "accumulate");
    accumulate_.dispatchThreads(cmd, push, buffers_->pixelCount);
    computeBarrier(cmd);
  }
  if (view != HeatmapView::None) {
    heatmap_->recordColorize(cmd, view, *buffers_, &timer_);
  } else {
    ScopedStage s(&timer_, cmd, "tonemap");
    tonemap_.dispatchThreads(cmd, push, buffers_->pixelCount);
    computeBarrier(cmd);
  }
  // Counters and readbacks are read by the host after the frame's fence.
  VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  toHost.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
  toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                       VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0, nullptr, 0, nullptr);
}

uint32_t PathTracer::heatmapBounce() const { return heatmapBounceShown(settings_); }

// The bounce loop of DESIGN.md: trace, learn, shade, then keys, sort and reorder before the next bounce.
// Trace and shade are dispatched indirectly over the live paths: all of them until a sort has moved the
// finished paths behind the live ones (GpuFrame::live).
void PathTracer::recordWavefront(VkCommandBuffer cmd, const gpu::PathStagePush& basePush) {
  gpu::PathStagePush push = basePush;
  const uint32_t n = buffers_->pathCount;
  const HeatmapView view = heatmapShown(settings_);
  const VkDeviceAddress keyParams = settings_.sorts() ? reorder_->keys().paramsAddress() : 0;
  const bool hasCache = settings_.sorts() && reorder_->keys().cache() != nullptr;
  {
    ScopedStage s(&timer_, cmd, "generate");
    generate_.dispatchThreads(cmd, push, n);
    computeBarrier(cmd);
  }
  for (uint32_t b = 0; b < settings_.bounces; ++b) {
    timer_.setBounce(static_cast<int>(b));
    push.bounce = b;
    {
      ScopedStage s(&timer_, cmd, "trace");
      (settings_.countSimt ? traceCounting_ : trace_).dispatchIndirect(cmd, push, buffers_->live.handle(), 4);
      computeBarrier(cmd);
    }
    recordTraceCounters(cmd, b);
    if (settings_.sorts()) reorder_->recordAfterTrace(cmd, *buffers_, push.stateSet, b, detailedStats_, &timer_);
    if (view != HeatmapView::None && view != HeatmapView::SortKey && b == heatmapBounce())
      heatmap_->recordGather(cmd, view, *buffers_, push.stateSet, keyParams, hasCache, false, &timer_);
    {
      ScopedStage s(&timer_, cmd, "shade");
      shade_.dispatchIndirect(cmd, push, buffers_->live.handle(), 4);
      computeBarrier(cmd);
    }
    if (b + 1 < settings_.bounces && settings_.sorts()) {
      reorder_->recordKeys(cmd, *buffers_, push.stateSet, b, detailedStats_, &timer_);
      if (view == HeatmapView::SortKey && b + 1 == heatmapBounce())
        heatmap_->recordGather(cmd, view, *buffers_, push.stateSet, keyParams, hasCache, false, &timer_);
      push.stateSet = reorder_->recordSortAndGather(cmd, *buffers_, push.stateSet, &timer_);
    }
  }
  timer_.setBounce(-1);
}

// Saves this trace's counters (rays, SIMT lanes) into the bounce's history slot and clears them; in the
// detailed mode also keeps the per-path traversal steps for the virtual warp efficiency.
void PathTracer::recordTraceCounters(VkCommandBuffer cmd, uint32_t bounce) {
  ScopedStage s(&timer_, cmd, "counters");
  VkBufferCopy copy{0, VkDeviceSize(bounce) * kCounterCount * 4, kCounterCount * 4};
  vkCmdCopyBuffer(cmd, buffers_->counters.handle(), buffers_->counterHistory.handle(), 1, &copy);
  if (detailedStats_) {
    // Released again by gatherCounters(): only the frame that asked for them holds these copies.
    if (stepsReadback_.size() <= bounce) stepsReadback_.resize(bounce + 1);
    stepsReadback_[bounce] = GpuBuffer(ctx_, buffers_->hitSteps.size(), MemoryKind::HostVisible);
    VkBufferCopy steps{0, 0, VkDeviceSize(buffers_->pathCount) * 4};
    vkCmdCopyBuffer(cmd, buffers_->hitSteps.handle(), stepsReadback_[bounce].handle(), 1, &steps);
  }
  computeBarrier(cmd);
  buffers_->counters.recordFill(cmd, 0);
  computeBarrier(cmd);
}

const FrameStats& PathTracer::renderFrame() {
  auto start = std::chrono::steady_clock::now();
  ctx_.submitAndWait([&](VkCommandBuffer cmd) { recordFrame(cmd); });
  double wall = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return finishFrame(wall);
}

const FrameStats& PathTracer::finishFrame(double wallMs) {
  stats_ = FrameStats{};
  stats_.frameIndex = frameIndex_;
  stats_.wallMs = wallMs;
  stats_.stages = timer_.collect();
  stats_.frameMs = timer_.spanMs();
  gatherCounters();
  if (settings_.sorts()) reorder_->finishFrame(stats_, detailedStats_);
  if (heatmapShown(settings_) != HeatmapView::None) heatmap_->readRange(heatmapShown(settings_), stats_);
  stats_.pathStateBytes = buffers_->pathStateBytes();
  stats_.sceneBytes = scene_->memoryBytes();
  double seconds = (stats_.frameMs > 0.0 ? stats_.frameMs : wallMs) * 1e-3;
  stats_.raysPerSecond = seconds > 0.0 ? static_cast<double>(stats_.raysTraced) / seconds : 0.0;
  ++frameIndex_;
  stats_.samplesPerPixel = frameIndex_ * settings_.sppPerFrame;
  return stats_;
}

void PathTracer::gatherCounters() {
  const bool mega = settings_.kernel == Kernel::Megakernel;
  const uint32_t rounds = mega ? 1 : settings_.bounces;
  const auto* history = static_cast<const uint32_t*>(buffers_->counterHistory.mapped());
  for (uint32_t b = 0; b < rounds; ++b) {
    const uint32_t* c = history + b * kCounterCount;
    BounceStats bs;
    bs.rays = c[kCounterRays];
    if (settings_.countSimt && c[kCounterSimtSlots] > 0)
      bs.simtEfficiency = static_cast<double>(c[kCounterSimtActive]) /
                          (static_cast<double>(c[kCounterSimtSlots]) * ctx_.info().subgroupSize);
    if (detailedStats_ && b < stepsReadback_.size()) {
      const auto* steps = static_cast<const uint32_t*>(stepsReadback_[b].mapped());
      WarpEfficiency w = virtualWarpEfficiency(steps, buffers_->pathCount, 32);
      bs.virtualWarpEfficiency = w.efficiency;
      bs.meanTraversalSteps = w.meanSteps;
    }
    stats_.raysTraced += bs.rays;
    stats_.bounces.push_back(bs);
  }
  stepsReadback_.clear();  // host-visible copies are only kept for the frame that asked for them
}

std::vector<uint32_t> PathTracer::readImage() const {
  return buffers_->image.downloadVector<uint32_t>(buffers_->pixelCount);
}

std::vector<glm::vec3> PathTracer::readRadiance() const {
  std::vector<glm::vec4> acc = buffers_->accumulation.downloadVector<glm::vec4>(buffers_->pixelCount);
  std::vector<glm::vec3> out(acc.size());
  for (size_t i = 0; i < acc.size(); ++i) out[i] = acc[i].w > 0.0f ? glm::vec3(acc[i]) / acc[i].w : glm::vec3(0.0f);
  return out;
}

}  // namespace raylab
