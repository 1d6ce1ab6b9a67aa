// PathTracer's side after a submission: a frame's statistics (stage times summed over the submissions of
// its steps, the counters and readbacks), and the images read back. path_tracer.cpp records the frames.
#include "renderer/path_tracer.h"

#include <algorithm>
#include <chrono>

#include "renderer/detail_stats.h"
#include "renderer/detail_sums.h"
#include "renderer/reorder/path_sorter.h"
#include "renderer/rt_tracer.h"
#include "renderer/heatmap/heatmap_pass.h"
#include "renderer/vk/vk_check.h"
#include "renderer/vk/vk_context.h"

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
  ++frameSubmissions_;  // each submission of steps is waited for before this
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
  stats_.commands = frameCommands_.total();
  stats_.stageCommands = frameCommands_.stages();
  stats_.submissions = frameSubmissions_;
  gatherCounters();
  if (settings_.sorts()) {
    pathSorter_->finishFrame(stats_);
    if (detailedStats_) gatherDetails();
    for (size_t b = 0; b < framePlan_.sortAfter.size() && b < stats_.bounces.size(); ++b) {
      stats_.bounces[b].sortedAfter = framePlan_.sortAfter[b];
      stats_.bounces[b].sortReason = framePlan_.reasons[b];
    }
    // Counting frames run a slower trace: they would teach the policy wrong costs. Detailed frames' passes are
    // the "counters" stage, which the policy does not read, so they teach it (a render with --stats is
    // detailed in every frame).
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
  // The frame's own work: a detailed frame's measuring passes would lower its rate.
  double seconds = (stats_.frameMs > 0.0 ? stats_.workMs() : stats_.wallMs) * 1e-3;
  stats_.raysPerSecond = seconds > 0.0 ? static_cast<double>(stats_.raysTraced) / seconds : 0.0;
  ++frameIndex_;
  stats_.samplesPerPixel = frameIndex_ * settings_.sppPerFrame;
  return stats_;
}

void PathTracer::gatherCounters() {
  const uint32_t rounds = countedBounces();
  const auto* history = static_cast<const uint32_t*>(buffers_->counterHistory.mapped());
  const bool learns = settings_.sorts() && pathSorter_->keys().hasCache();
  if (learns) stats_.lengthCacheResets = 0;
  for (uint32_t b = 0; b < rounds; ++b) {
    const uint32_t* c = history + b * RL_COUNTER_STRIDE;
    if (learns) stats_.lengthCacheResets += c[RL_COUNTER_CACHE_RESETS];
    BounceStats bs;
    bs.rays = c[RL_COUNTER_RAYS];
    if (settings_.countSimt && !usesRt() && c[RL_COUNTER_SIMT_SLOTS] > 0)
      bs.simtEfficiency = static_cast<double>(c[RL_COUNTER_SIMT_ACTIVE]) /
                          (static_cast<double>(c[RL_COUNTER_SIMT_SLOTS]) * ctx_.info().subgroupSize);
    if (detailedStats_ && details_->measuredWarps(b)) {
      const WarpFigures w = warpFigures(details_->sums(b), buffers_->pathCount);
      bs.virtualWarpEfficiency = w.efficiency;
      bs.meanTraversalSteps = w.meanSteps;
    }
    if (settings_.kernel == Kernel::Wavefront) {
      double traceMs = 0.0;
      for (const StageTime& t : stats_.stages)
        if (t.stage == "trace" && t.bounce == int(b)) traceMs += t.ms;
      if (traceMs > 0.0) bs.traceRaysPerSecond = bs.rays / (traceMs * 1e-3);
    }
    stats_.raysTraced += bs.rays;
    stats_.bounces.push_back(bs);
  }
}

// The key figures of a detailed frame, from its sums: prediction accuracy and distinct keys for the bounces
// whose rays were keyed and sorted (the others keep "not measured"), and the cache's occupancy.
void PathTracer::gatherDetails() {
  for (uint32_t b = 1; b < stats_.bounces.size(); ++b) {
    if (!details_->measuredPrediction(b)) continue;
    const PredictionFigures p = predictionFigures(details_->sums(b));
    BounceStats& bs = stats_.bounces[b];
    if (p.evaluated > 0) {
      bs.predictionErrorMean = p.meanError;
      bs.predictionErrorMedian = p.medianError;
      bs.cellHitRate = p.cellHitRate;
    }
    bs.distinctKeys = details_->sums(b).distinctKeys;
  }
  const uint32_t entries = pathSorter_->keys().cacheEntryCount();
  if (details_->measuredCache() && entries > 0)
    stats_.lengthCacheOccupancy = double(details_->sums(0).cacheUsed) / double(entries);
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
