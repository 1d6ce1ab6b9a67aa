// PathTracer's side after a submission: a frame's statistics (stage times summed over the submissions of
// its steps, the counters and readbacks), and the images read back. path_tracer.cpp records the frames.
#include "renderer/path_tracer.h"

#include <algorithm>
#include <chrono>

#include "renderer/reorder/path_sorter.h"
#include "renderer/rt_tracer.h"
#include "renderer/heatmap_pass.h"
#include "renderer/vk/vk_check.h"
#include "renderer/vk/vk_context.h"
#include "renderer/warp_efficiency.h"

namespace raylab {

const FrameStats& PathTracer::renderFrame() {
  auto start = std::chrono::steady_clock::now();
  ctx_.submitAndWait([&](VkCommandBuffer cmd) { recordFrame(cmd); });
  double wall = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return finishFrame(wall);
}

const FrameStats& PathTracer::finishFrame(double wallMs) {
  const FrameStats* whole = finishSteps(wallMs);
  if (!whole) throw VulkanError("finishFrame after steps that did not end the frame");
  return *whole;
}

const FrameStats* PathTracer::finishSteps(double wallMs) {
  const std::vector<StageTime> stages = timer_.collect();
  lastStepTimes_.clear();
  for (const RecordedStep& r : recorded_) {
    StepTime t{steps_[r.step].name, steps_[r.step].bounce, 0.0};
    for (uint32_t s = r.firstScope; s < r.endScope && s < stages.size(); ++s) t.ms += stages[s].ms;
    lastStepTimes_.push_back(std::move(t));
  }
  recorded_.clear();
  addStepStages(stages);
  frameGpuMs_ += timer_.spanMs();
  frameWallMs_ += wallMs;
  if (steps_.empty() || nextStep_ < steps_.size()) return nullptr;
  steps_.clear();
  nextStep_ = 0;
  return &completeFrame();
}

// A submission's stage times join the frame's: the same (stage, bounce) adds up (the detailed readbacks'
// "counters"), so the frame reports the stages a whole frame would, and their sum still matches the GPU
// time (the sum of the submissions' spans).
void PathTracer::addStepStages(const std::vector<StageTime>& stages) {
  for (const StageTime& t : stages) {
    auto same = std::find_if(frameStages_.begin(), frameStages_.end(),
                             [&](const StageTime& s) { return s.stage == t.stage && s.bounce == t.bounce; });
    if (same != frameStages_.end())
      same->ms += t.ms;
    else
      frameStages_.push_back(t);
  }
}

const FrameStats& PathTracer::completeFrame() {
  stats_ = FrameStats{};
  stats_.frameIndex = frameIndex_;
  stats_.wallMs = frameWallMs_;
  stats_.stages = std::move(frameStages_);
  frameStages_.clear();
  stats_.frameMs = frameGpuMs_;
  gatherCounters();
  if (settings_.sorts()) {
    pathSorter_->finishFrame(stats_, detailedStats_);
    for (size_t b = 0; b < framePlan_.sortAfter.size() && b < stats_.bounces.size(); ++b) {
      stats_.bounces[b].sortedAfter = framePlan_.sortAfter[b];
      stats_.bounces[b].sortReason = framePlan_.reasons[b];
    }
    // Counting frames run a slower trace: they would teach the policy wrong costs. Detailed frames' readbacks
    // lie outside the timed stages, so they teach it (a render with --stats is detailed in every frame).
    if (!settings_.countSimt) sortPolicy_.record(framePlan_, stats_.stages);
  }
  heatmap_->finishFrame(stats_);
  stats_.pathStateBytes = buffers_->pathStateBytes();
  stats_.sceneBytes = scene_->memoryBytes();
  if (usesRt()) {
    stats_.accelerationStructureBytes = rt_->accelerationStructureBytes();
    stats_.traversalStatsUnavailable = "not available with the rt tracer";
    // The step heatmaps would show the zeros the rt stages write: the legend says why instead.
    if (settings_.heatmap == HeatmapView::TraversalSteps || settings_.heatmap == HeatmapView::WarpEfficiency)
      stats_.heatmap.emptyReason = "traversal steps: not available with the rt tracer";
  }
  double seconds = (stats_.frameMs > 0.0 ? stats_.frameMs : stats_.wallMs) * 1e-3;
  stats_.raysPerSecond = seconds > 0.0 ? static_cast<double>(stats_.raysTraced) / seconds : 0.0;
  ++frameIndex_;
  stats_.samplesPerPixel = frameIndex_ * settings_.sppPerFrame;
  return stats_;
}

void PathTracer::gatherCounters() {
  const uint32_t rounds = countedBounces();
  const auto* history = static_cast<const uint32_t*>(buffers_->counterHistory.mapped());
  for (uint32_t b = 0; b < rounds; ++b) {
    const uint32_t* c = history + b * RL_COUNTER_STRIDE;
    BounceStats bs;
    bs.rays = c[RL_COUNTER_RAYS];
    if (settings_.countSimt && !usesRt() && c[RL_COUNTER_SIMT_SLOTS] > 0)
      bs.simtEfficiency = static_cast<double>(c[RL_COUNTER_SIMT_ACTIVE]) /
                          (static_cast<double>(c[RL_COUNTER_SIMT_SLOTS]) * ctx_.info().subgroupSize);
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
