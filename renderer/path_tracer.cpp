#include "renderer/path_tracer.h"

#include <algorithm>
#include <cmath>

#include "renderer/reorder/key_functions.h"
#include "renderer/reorder/path_sorter.h"
#include "renderer/rt_tracer.h"
#include "renderer/heatmap_pass.h"
#include "renderer/heatmap_rules.h"
#include "renderer/vk/stage_timer.h"
#include "renderer/vk/vk_check.h"
#include "renderer/vk/vk_context.h"

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
    : PathTracer(ctx, scene, std::make_shared<GpuSceneData>(ctx, scene), settings, camera) {}

PathTracer::PathTracer(const PathTracer& sameScene, const Scene& scene, const Settings& settings,
                       const Viewpoint& camera)
    : PathTracer(sameScene.ctx_, scene, sameScene.scene_, settings, camera) {}

PathTracer::PathTracer(const VulkanContext& ctx, const Scene& scene, std::shared_ptr<GpuSceneData> gpuScene,
                       const Settings& settings, const Viewpoint& camera)
    : ctx_(ctx),
      settings_(settings),
      camera_(camera),
      scene_(std::move(gpuScene)),
      generate_(ctx, "generate", sizeof(gpu::PathStagePush), kGroup),
      trace_(ctx, "trace", sizeof(gpu::PathStagePush), kGroup, {0}),
      traceCounting_(ctx, "trace", sizeof(gpu::PathStagePush), kGroup, {1}),
      shade_(ctx, "shade", sizeof(gpu::PathStagePush), kGroup),
      accumulate_(ctx, "accumulate", sizeof(gpu::PathStagePush), kGroup),
      tonemap_(ctx, "tonemap", sizeof(gpu::PathStagePush), kGroup),
      megakernel_(ctx, "megakernel", sizeof(gpu::PathStagePush), kGroup, {0}),
      megakernelCounting_(ctx, "megakernel", sizeof(gpu::PathStagePush), kGroup, {1}),
      timer_(ctx) {
  checkSupported(settings_);
  allocate();
  if (usesRt()) rt_ = std::make_unique<RtTracer>(ctx_, *scene_);
  pathSorter_ = std::make_unique<PathSorter>(ctx, scene, settings_, camera_.position, buffers_->pathCount);
  restartAccumulation();
}

PathTracer::~PathTracer() { vkDeviceWaitIdle(ctx_.device()); }

void PathTracer::allocate() {
  buffers_.reset();
  buffers_ = std::make_unique<PathBuffers>(ctx_, settings_.width, settings_.height, settings_.sppPerFrame);
  heatmap_ = std::make_unique<HeatmapPass>(ctx_, buffers_->pixelCount);
}

void PathTracer::restartAccumulation() {
  frameIndex_ = 0;
  sliceNext_ = sliceEnd_ = 0;
  ctx_.submitAndWait([&](VkCommandBuffer cmd) { buffers_->accumulation.recordFill(cmd, 0); });
}

// Settings the device cannot run (the rt tracer or SER without their extensions) are refused here too; the
// commands check first (unsupportedSettings) to exit with a usage error, the window greys them out.
void PathTracer::checkSupported(const Settings& settings) const {
  if (std::string why = unsupportedSettings(ctx_.info(), settings); !why.empty()) throw VulkanError(why);
}

// The one place a change of settings or camera is acted on; every part gets the same SettingsChange.
void PathTracer::apply(const SettingsChange& change) {
  sliceNext_ = sliceEnd_ = 0;  // a partial frame was made with the old settings or camera: start it again
  if (change.reallocate) allocate();
  if (usesRt() && !rt_) rt_ = std::make_unique<RtTracer>(ctx_, *scene_);
  pathSorter_->apply(settings_, camera_.position, buffers_->pathCount, change);
  if (change.reallocate || change.resetAccumulation) restartAccumulation();
}

void PathTracer::applySettings(const Settings& next) {
  checkSupported(next);
  SettingsChange change = SettingsChange::between(settings_, next);
  if (change.resetSortCosts) sortPolicy_.reset();
  settings_ = next;
  apply(change);
}

const KeyStage& PathTracer::keyStage() const { return pathSorter_->keys(); }

void PathTracer::setCamera(const Viewpoint& camera) {
  camera_ = camera;
  apply(SettingsChange::cameraMove(settings_));
}

// A heatmap gathers each slice's paths into their own pixels (the value range and counts add up over the
// slices), so most views render in slices like the image. Two depend on the whole frame's order: sort-key
// ranks (a key's place among all of the bounce's sorted keys) and warp efficiency (the 32 slots a path
// shares a warp with).
bool PathTracer::needsWholeFrames() const {
  const HeatmapView view = heatmapShown(settings_);
  return (view == HeatmapView::SortKey && settings_.heatmapKeyColour == HeatmapKeyColour::Rank) ||
         view == HeatmapView::WarpEfficiency;
}

void PathTracer::setDetailedStats(bool on) {
  if (on != detailedStats_) sliceNext_ = sliceEnd_ = 0;
  detailedStats_ = on;
}

// One frame: generate, the bounces, accumulate, then tonemap (or the heatmap instead).
void PathTracer::recordFrame(VkCommandBuffer cmd) {
  sliceNext_ = 0;  // a partial frame, if any, is abandoned
  recordSlice(cmd, buffers_->pathCount);
}

uint32_t PathTracer::recordSlice(VkCommandBuffer cmd, uint32_t paths) {
  const uint32_t total = buffers_->pathCount;
  if (needsWholeFrames()) sliceNext_ = 0, paths = total;
  const uint32_t first = sliceNext_;
  const uint32_t count = std::clamp(paths, 1u, total - first);
  const bool starts = first == 0, ends = first + count == total;
  if (starts) {
    framePlan_ = settings_.sorts() ? sortPolicy_.plan(settings_.sortPolicy, settings_.bounces) : SortPlan{};
    sliceStages_.clear();
    sliceGpuMs_ = sliceWallMs_ = 0.0;
  }
  timer_.reset(cmd);
  // Every command of the slice is inside a timed stage, so the stages account for the frame's GPU time.
  recordStage(cmd, &timer_, "setup", [&] {
    recordFrameBlock(cmd, first, count);
    if (starts) {
      buffers_->counters.recordFill(cmd, 0);  // the frame's counters sum over its slices
      computeBarrier(cmd);
      const bool sorting = settings_.sorts();
      heatmap_->beginFrame(cmd, settings_, sorting ? pathSorter_->keys().paramsAddress() : 0,
                           sorting ? &pathSorter_->keys().grid().gpu : nullptr, sorting && pathSorter_->keys().hasCache());
    }
  });
  const gpu::PathStagePush push{buffers_->frameBlock.address(), 0, 0};
  if (settings_.kernel == Kernel::Megakernel)
    recordMegakernel(cmd, push, {first, count});
  else
    recordWavefront(cmd, push, {first, count});
  if (ends) {
    recordStage(cmd, &timer_, "accumulate", [&] { accumulate_.dispatchThreads(cmd, push, buffers_->pixelCount); });
    if (!heatmap_->colorize(cmd, *buffers_, &timer_))
      recordStage(cmd, &timer_, "tonemap", [&] { tonemap_.dispatchThreads(cmd, push, buffers_->pixelCount); });
    recordCountersToHost(cmd);
  }
  sliceEnd_ = first + count;
  return count;
}

// The GpuFrame block every stage reads (addresses, camera, frame parameters, the slice's paths).
void PathTracer::recordFrameBlock(VkCommandBuffer cmd, uint32_t firstPath, uint32_t paths) {
  gpu::GpuFrame frame = buffers_->addresses();
  frame.camera = makeGpuCamera(camera_, settings_.width, settings_.height);
  frame.scene = scene_->block();
  frame.scene.tlas = usesRt() ? rt_->tlasAddress() : 0;
  frame.keyParams = settings_.sorts() ? pathSorter_->keys().paramsAddress() : 0;
  frame.width = settings_.width;
  frame.height = settings_.height;
  frame.sppPerFrame = settings_.sppPerFrame;
  frame.pathCount = paths;
  frame.firstPath = firstPath;
  frame.dispatchRowGroups = ctx_.info().dispatchRowGroups;  // for the indirect sizes shaders write
  frame.frameIndex = frameIndex_;
  frame.bounceCount = settings_.bounces;
  frame.seed = settings_.seed;
  frame.exposure = settings_.exposure;
  vkCmdUpdateBuffer(cmd, buffers_->frameBlock.handle(), 0, sizeof(frame), &frame);
  if (settings_.compacts() && settings_.bounces > 1) {
    // The blocks compacting shades append to start empty: no paths, zero groups of size (x, 1, 1).
    std::vector<uint32_t> empty(RL_LIVE_WORDS * (settings_.bounces - 1), 0);
    for (size_t b = 0; b < empty.size(); b += RL_LIVE_WORDS) empty[b + RL_LIVE_DISPATCH + 1] = empty[b + RL_LIVE_DISPATCH + 2] = 1;
    vkCmdUpdateBuffer(cmd, buffers_->live.handle(), PathBuffers::liveAppendOffset(0), empty.size() * 4, empty.data());
  }
  computeBarrier(cmd);
}

void PathTracer::recordMegakernel(VkCommandBuffer cmd, const gpu::PathStagePush& push, PathRange slice) {
  const uint32_t n = slice.count;
  const ComputePipeline& megakernel = settings_.countSimt ? megakernelCounting_ : megakernel_;
  recordStage(cmd, &timer_, "megakernel", [&] {
    if (!usesRt()) {
      megakernel.dispatchThreads(cmd, push, n);
    } else if (settings_.ser == Ser::Off) {
      rt_->megakernel(cmd, push, n);
    } else {
      // The hint: the top bits (at most 16) of the key Settings::strategy gives each ray.
      const KeyStrategy hint = settings_.ser == Ser::Hint ? settings_.strategy : KeyStrategy::None;
      const uint32_t bits = hint == KeyStrategy::None ? 0 : spatialKeyBits(hint, pathSorter_->keys().grid().gpu);
      gpu::RtSerPush ser{push.frame, hint == KeyStrategy::None ? 0 : pathSorter_->keys().paramsAddress(),
                         bits > 16 ? bits - 16 : 0, std::min(bits, 16u)};
      rt_->serMegakernel(cmd, ser, hint, n);
    }
  });
  if (detailedStats_ && !usesRt()) recordStepsReadback(cmd, 0, slice);
  heatmap_->afterMegakernel(cmd, *buffers_, &timer_);
}

const ComputePipeline& PathTracer::shadeVariant(bool compact, bool traceFirst) {
  if (!compact && !traceFirst) return shade_;
  std::optional<ComputePipeline>& p = shadeVariants_[compact ? 1 : 0][traceFirst ? 1 : 0];
  if (!p)
    p.emplace(ctx_, "shade", sizeof(gpu::PathStagePush), kGroup,
              std::vector<uint32_t>{static_cast<uint32_t>(KeyStrategy::None), compact ? 1u : 0u, traceFirst ? 1u : 0u});
  return *p;
}

const ComputePipeline& PathTracer::gatheringTrace(bool counting) {
  std::optional<ComputePipeline>& p = gatheringTrace_[counting ? 1 : 0];
  if (!p) p.emplace(ctx_, "trace", sizeof(gpu::PathStagePush), kGroup, std::vector<uint32_t>{counting ? 1u : 0u, 1u});
  return *p;
}

// The bounce loop: trace, learn, shade, then keys, sort and reorder before the next bounce where the sort
// policy's plan says so (learn only for rays that were sorted). Trace and shade are dispatched indirectly
// over the live paths: all of them until a sort has moved the finished paths behind the live ones
// (GpuFrame::live); a bounce that does not sort keeps the last sort's order and live count.
// Settings::fusion folds the keys into shade and the reorder into the next trace: the stage times then
// report them as part of "shade" and "trace", since they are no longer passes of their own.
// Settings::compaction: every shade but the last bounce's packs the live paths into the other state set and
// its own block of GpuFrame::live, which becomes the live block (the copy is timed as part of "shade"), and
// gives the slots it visited the dead key, so keys, sort and reorder after it see a live prefix with dead
// keys behind it as after a sort. Not where shade makes the keys (Settings::fusion keys): a path's key would
// have to go to its new slot, which another subgroup may be marking dead.
void PathTracer::recordWavefront(VkCommandBuffer cmd, gpu::PathStagePush push, PathRange slice) {
  const uint32_t n = slice.count;
  const bool sorting = settings_.sorts();
  const ComputePipeline& trace = settings_.countSimt ? traceCounting_ : trace_;
  const VkBuffer live = buffers_->live.handle();
  const VkDeviceSize liveDispatch = PathBuffers::kLiveDispatchOffset;
  bool gatherInTrace = false;  // the last sort's reorder is left to this bounce's trace
  recordStage(cmd, &timer_, "generate", [&] { generate_.dispatchThreads(cmd, push, n); });
  for (uint32_t b = 0; b < settings_.bounces; ++b) {
    timer_.setBounce(static_cast<int>(b));
    push.bounce = b;
    const bool sortedBefore = sorting && b > 0 && framePlan_.sortAfter[b - 1];
    const bool sortAfter = sorting && b + 1 < settings_.bounces && framePlan_.sortAfter[b];
    const bool keysInShade = sortAfter && settings_.fusesKeys();
    const bool compacts = settings_.compacts() && !keysInShade && b + 1 < settings_.bounces;
    // shade.comp as this bounce needs it; `traceFirst`: it also does the trace (Settings::traceShade).
    auto shade = [&](bool traceFirst) {
      if (compacts) {
        shadeVariant(true, traceFirst).dispatchIndirect(cmd, push, live, liveDispatch);
        computeBarrier(cmd);
        const VkBufferCopy packed{PathBuffers::liveAppendOffset(b), 0, PathBuffers::kLiveBlockBytes};
        vkCmdCopyBuffer(cmd, live, live, 1, &packed);
      } else {
        (keysInShade ? pathSorter_->shadeWithKeys() : shadeVariant(false, traceFirst))
            .dispatchIndirect(cmd, push, live, liveDispatch);
      }
    };
    // One dispatch for trace and shade where nothing between them reads the hits: no reorder in this trace,
    // no keys in shade, no learning from sorted rays, no detailed statistics, no heatmap of this bounce.
    const bool learns = sortedBefore && usesLengthCache(settings_.strategy);
    if (settings_.fusesTraceShade() && !gatherInTrace && !keysInShade && !learns && !detailedStats_ &&
        !heatmap_->readsAfterTrace(b)) {
      recordStage(cmd, &timer_, "trace+shade", [&] { shade(true); });
    } else {
      recordStage(cmd, &timer_, "trace", [&] {
        if (usesRt())
          rt_->traceRays(cmd, push, n);  // every path; the shader skips those past the live count
        else if (gatherInTrace)
          gatheringTrace(settings_.countSimt).dispatchThreads(cmd, push, n);  // every slot: it finds the live count
        else
          trace.dispatchIndirect(cmd, push, live, liveDispatch);
      });
      if (gatherInTrace) push.stateSet = 1u - push.stateSet, gatherInTrace = false;
      if (detailedStats_ && !usesRt()) recordStepsReadback(cmd, b, slice);
      if (sorting)
        pathSorter_->recordAfterTrace(cmd, *buffers_, slice, push.stateSet, b, sortedBefore, detailedStats_, &timer_);
      heatmap_->afterTrace(cmd, *buffers_, push.stateSet, b, &timer_);
      recordStage(cmd, &timer_, "shade", [&] {
        if (usesRt())
          rt_->shade(cmd, push, n);
        else
          shade(false);
      });
    }
    if (compacts) push.stateSet = 1u - push.stateSet;
    if (sortAfter) {
      pathSorter_->recordKeys(cmd, *buffers_, slice, push.stateSet, b, keysInShade, detailedStats_, &timer_);
      heatmap_->afterKeys(cmd, *buffers_, push.stateSet, b, &timer_);
      pathSorter_->recordSort(cmd, *buffers_, n, &timer_);
      // The sort-rank heatmap reads the reordered set right after the sort: that bounce gathers on its own.
      gatherInTrace = settings_.fusesGather() && !heatmap_->readsAfterSort(b);
      if (!gatherInTrace) {
        push.stateSet = pathSorter_->recordGather(cmd, *buffers_, n, push.stateSet, &timer_);
        heatmap_->afterSort(cmd, *buffers_, push.stateSet, b, &timer_);
      }
    }
  }
  timer_.setBounce(-1);
}

// Detailed mode: keeps this trace's per-path traversal steps (the next trace overwrites them) for the
// virtual warp efficiency, in dispatch order: a slice's slots go to its part of the frame's readback, so the
// warps are those of the whole frame where slices are whole warps (LiveRender's are whole work groups).
// Released again by gatherCounters(): only the frame that asked holds them.
void PathTracer::recordStepsReadback(VkCommandBuffer cmd, uint32_t bounce, PathRange slice) {
  ScopedStage s(&timer_, cmd, "counters");
  if (stepsReadback_.size() <= bounce) stepsReadback_.resize(bounce + 1);
  if (stepsReadback_[bounce].size() != buffers_->hitSteps.size())
    stepsReadback_[bounce] = GpuBuffer(ctx_, buffers_->hitSteps.size(), MemoryKind::HostVisible);
  VkBufferCopy steps{0, VkDeviceSize(slice.first) * 4, VkDeviceSize(slice.count) * 4};
  vkCmdCopyBuffer(cmd, buffers_->hitSteps.handle(), stepsReadback_[bounce].handle(), 1, &steps);
  computeBarrier(cmd);
}

uint32_t PathTracer::countedBounces() const { return settings_.kernel == Kernel::Megakernel ? 1 : settings_.bounces; }

// This frame's counters, one slot set per bounce, in one copy; then everything the host reads after the
// frame's fence (counters, readbacks) is made visible to it.
void PathTracer::recordCountersToHost(VkCommandBuffer cmd) {
  ScopedStage s(&timer_, cmd, "counters");
  VkBufferCopy counters{0, 0, PathBuffers::counterBytes(countedBounces())};
  vkCmdCopyBuffer(cmd, buffers_->counters.handle(), buffers_->counterHistory.handle(), 1, &counters);
  VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  toHost.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
  toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                       VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0, nullptr, 0, nullptr);
}

}  // namespace raylab
