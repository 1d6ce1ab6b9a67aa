#include "renderer/path_tracer.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "renderer/detail_stats.h"
#include "renderer/reorder/key_functions.h"
#include "renderer/reorder/path_sorter.h"
#include "renderer/rt_tracer.h"
#include "renderer/heatmap/heatmap_pass.h"
#include "renderer/heatmap/heatmap_rules.h"
#include "renderer/vk/size_writes.h"
#include "renderer/vk/stage_timer.h"
#include "renderer/vk/vk_check.h"
#include "renderer/vk/vk_context.h"

namespace raylab {

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

namespace {
// A path stage (one thread per path) as a pipeline built on first use, with its variant's constants.
LazyPipeline pathStage(const VulkanContext& ctx, const char* shader, SpecConstants variant,
                       WritesSizes writesSizes = WritesSizes::No) {
  return LazyPipeline(ctx, shader, sizeof(gpu::PathStagePush), RL_PATH_GROUP_SIZE, std::move(variant), writesSizes);
}
// trace.comp's variant: SIMT counting, the fused gather (which writes the next dispatch's size), step counting.
LazyPipeline traceStage(const VulkanContext& ctx, uint32_t countSimt, uint32_t fusesGather, uint32_t countsSteps) {
  return pathStage(ctx, "trace",
                   {{RL_SPEC_COUNT_SIMT, countSimt}, {RL_SPEC_FUSES_GATHER, fusesGather}, {RL_SPEC_COUNTS_STEPS, countsSteps}},
                   fusesGather ? WritesSizes::Yes : WritesSizes::No);
}
// megakernel.comp's variant: SIMT counting, step counting, and the traversal it holds (RL_BVH_BINARY or
// RL_BVH_WIDE: traversalOf(Settings::bvh), fixed so that its code holds one traversal; bvh_traverse.glsl says why).
LazyPipeline megakernelStage(const VulkanContext& ctx, uint32_t countSimt, uint32_t countsSteps, uint32_t traversal) {
  return pathStage(ctx, "megakernel",
                   {{RL_SPEC_COUNT_SIMT, countSimt}, {RL_SPEC_COUNTS_STEPS, countsSteps}, {RL_SPEC_BVH_LAYOUT, traversal}});
}
// shade.comp's bounce loop (Settings::traceShade loop), holding one traversal as the megakernel does
// (bvh_traverse.glsl's RL_SPEC_BVH_LAYOUT says what that measured).
LazyPipeline shadeLoopStage(const VulkanContext& ctx, uint32_t traversal) {
  return pathStage(ctx, "shade", {{RL_SPEC_COMPACT, 0}, {RL_SPEC_FUSES_TRACE_SHADE, 1}, {RL_SPEC_LOOPS_BOUNCES, 1},
                                  {RL_SPEC_BVH_LAYOUT, traversal}});
}
}  // namespace

PathTracer::PathTracer(const VulkanContext& ctx, const Scene& scene, const Settings& settings, const Viewpoint& camera)
    : PathTracer(ctx, scene, std::make_shared<GpuSceneData>(ctx, scene, settings.wideCollapse, settings.bvhReinsert,
                                                                settings.bvhPresplit), settings, camera) {}

PathTracer::PathTracer(const PathTracer& sameScene, const Scene& scene, const Settings& settings,
                       const Viewpoint& camera)
    : PathTracer(sameScene.ctx_, scene, sameScene.scene_, settings, camera) {}

PathTracer::PathTracer(const VulkanContext& ctx, const Scene& scene, std::shared_ptr<GpuSceneData> gpuScene,
                       const Settings& settings, const Viewpoint& camera)
    : ctx_(ctx),
      settings_(settings),
      camera_(camera),
      scene_(std::move(gpuScene)),
      generate_(ctx, "generate", sizeof(gpu::PathStagePush), RL_PATH_GROUP_SIZE, {}, WritesSizes::Yes),
      accumulate_(ctx, "accumulate", sizeof(gpu::PathStagePush), RL_PATH_GROUP_SIZE),
      tonemap_(ctx, "tonemap", sizeof(gpu::PathStagePush), RL_PATH_GROUP_SIZE),
      // The gathering trace finds the live count after a sort and the compacting shade appends the live
      // paths: both write the next dispatch's size.
      trace_{{{traceStage(ctx, 0, 0, 0), traceStage(ctx, 0, 0, 1)}, {traceStage(ctx, 0, 1, 0), traceStage(ctx, 0, 1, 1)}},
              {{traceStage(ctx, 1, 0, 0), traceStage(ctx, 1, 0, 1)}, {traceStage(ctx, 1, 1, 0), traceStage(ctx, 1, 1, 1)}}},
      shade_{{pathStage(ctx, "shade", {{RL_SPEC_COMPACT, 0}, {RL_SPEC_FUSES_TRACE_SHADE, 0}}),
               pathStage(ctx, "shade", {{RL_SPEC_COMPACT, 0}, {RL_SPEC_FUSES_TRACE_SHADE, 1}})},
              {pathStage(ctx, "shade", {{RL_SPEC_COMPACT, 1}, {RL_SPEC_FUSES_TRACE_SHADE, 0}}, WritesSizes::Yes),
               pathStage(ctx, "shade", {{RL_SPEC_COMPACT, 1}, {RL_SPEC_FUSES_TRACE_SHADE, 1}}, WritesSizes::Yes)}},
      megakernel_{{{megakernelStage(ctx, 0, 0, 0), megakernelStage(ctx, 0, 0, 1)},
                   {megakernelStage(ctx, 0, 1, 0), megakernelStage(ctx, 0, 1, 1)}},
                  {{megakernelStage(ctx, 1, 0, 0), megakernelStage(ctx, 1, 0, 1)},
                   {megakernelStage(ctx, 1, 1, 0), megakernelStage(ctx, 1, 1, 1)}}},
      shadeLoop_{shadeLoopStage(ctx, RL_BVH_BINARY), shadeLoopStage(ctx, RL_BVH_WIDE)},
      timer_(ctx) {
  checkSupported(settings_);
  allocate();
  if (usesRt()) rt_ = std::make_unique<RtTracer>(ctx_, *scene_);
  pathSorter_ = std::make_unique<PathSorter>(ctx, scene, settings_, camera_.position, buffers_->pathCount);
  details_ = std::make_unique<DetailStats>(ctx);
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
  abandonFrame();
  ctx_.submitAndWait([&](VkCommandBuffer cmd) { buffers_->accumulation.recordFill(cmd, 0); });
}

// Settings the device cannot run (the rt tracer or SER without their extensions) are refused here too; the
// commands check first (unsupportedSettings) to exit with a usage error, the window greys them out.
void PathTracer::checkSupported(const Settings& settings) const {
  // The scene's wide BVH was collapsed one way: another is another scene (the window builds it again).
  if (settings.wideCollapse != scene_->wideCollapse())
    throw std::logic_error("--wide-collapse " + toString(settings.wideCollapse) + " for a scene collapsed " +
                           toString(scene_->wideCollapse()) + ": build the tracer again");
  if (settings.bvhReinsert != scene_->reinsertPasses())
    throw std::logic_error("--bvh-reinsert " + std::to_string(settings.bvhReinsert) + " for a scene built with " +
                           std::to_string(scene_->reinsertPasses()) + ": build the tracer again");
  if (settings.bvhPresplit != scene_->presplit())
    throw std::logic_error("--bvh-presplit " + std::to_string(settings.bvhPresplit) + " for a scene built with " +
                           std::to_string(scene_->presplit()) + ": build the tracer again");
  if (std::string why = unsupportedSettings(ctx_.info(), settings); !why.empty()) throw VulkanError(why);
}

// The one place a change of settings or camera is acted on; every part gets the same SettingsChange.
void PathTracer::apply(const SettingsChange& change) {
  abandonFrame();  // a partial frame was made with the old settings or camera: start it again
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

void PathTracer::setDetailedStats(bool on) {
  if (on != detailedStats_) abandonFrame();
  detailedStats_ = on;
}

// The steps are built again for the next frame: its plan, fusions and state sets may differ.
void PathTracer::abandonFrame() {
  steps_.clear();
  nextStep_ = 0;
  recorded_.clear();
}

// One frame: generate, the bounces, accumulate, then tonemap (or the heatmap instead): all its steps.
void PathTracer::recordFrame(VkCommandBuffer cmd) {
  abandonFrame();  // a partial frame, if any, is abandoned
  recordSteps(cmd, UINT32_MAX);
}

std::span<const FrameStep> PathTracer::pendingSteps() {
  if (steps_.empty()) buildSteps();
  return std::span<const FrameStep>(steps_).subspan(nextStep_);
}

uint32_t PathTracer::recordSteps(VkCommandBuffer cmd, uint32_t count) {
  const std::span<const FrameStep> pending = pendingSteps();
  if (nextStep_ == 0) {
    frameStages_.clear();
    frameGpuMs_ = frameWallMs_ = 0.0;
    frameCommands_.clear();
    frameSubmissions_ = 0;
  }
  CountCommands counting(cmd, frameCommands_);
  const uint32_t n = std::clamp<uint32_t>(count, 1u, uint32_t(pending.size()));
  timer_.reset(cmd);
  recorded_.clear();
  // Every command of a step is inside a timed stage, so the stages account for the frame's GPU time.
  for (uint32_t i = 0; i < n; ++i) {
    const FrameStep& step = pending[i];
    const uint32_t firstScope = timer_.scopeCount();
    timer_.setBounce(step.bounce);
    step.record(cmd);
    recorded_.push_back({nextStep_ + i, firstScope, timer_.scopeCount()});
  }
  timer_.setBounce(-1);
  nextStep_ += n;
  return n;
}

// The GpuFrame block every stage reads (addresses, camera, frame parameters, the frame's paths).
void PathTracer::recordFrameBlock(VkCommandBuffer cmd) {
  gpu::GpuFrame frame = buffers_->addresses();
  frame.camera = makeGpuCamera(camera_, settings_.width, settings_.height);
  frame.scene = scene_->block(settings_.bvh);
  frame.scene.tlas = usesRt() ? rt_->tlasAddress() : 0;
  frame.keyParams = settings_.sorts() ? pathSorter_->keys().paramsAddress() : 0;
  frame.width = settings_.width;
  frame.height = settings_.height;
  frame.sppPerFrame = settings_.sppPerFrame;
  frame.pathCount = buffers_->pathCount;
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
    updateSizes(cmd, buffers_->live.handle(), PathBuffers::liveAppendOffset(0), empty.size() * 4, empty.data());
  }
  computeBarrier(cmd);
}

uint32_t PathTracer::countedBounces() const { return settings_.kernel == Kernel::Megakernel ? 1 : settings_.bounces; }

// This frame's counters, one slot set per bounce, in one copy; then everything the host reads after the
// frame's fence (counters, readbacks) is made visible to it.
void PathTracer::recordCountersToHost(VkCommandBuffer cmd) {
  ScopedStage s(&timer_, cmd, "counters");
  VkBufferCopy counters{0, 0, PathBuffers::counterBytes(countedBounces())};
  vkCmdCopyBuffer(cmd, buffers_->counters.handle(), buffers_->counterHistory.handle(), 1, &counters);
  if (detailedStats_) details_->recordToHost(cmd);
  hostReadBarrier(cmd);
}

}  // namespace raylab
