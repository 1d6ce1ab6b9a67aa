// What the renderer reports back each frame: the UI reads it, the CLI writes it as JSON, the benchmark
// aggregates it. Plain data, filled by the renderer; nothing here reaches into it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "renderer/frame_commands.h"
#include "renderer/heatmap/heatmap_stats.h"
#include "renderer/stages.h"

namespace raylab {

struct StageTime {
  std::string stage;  // generate, trace, learn, shade, keys, oracle-trace, sort, reorder, accumulate, tonemap, megakernel
  int bounce = -1;    // -1 for stages outside the bounce loop
  double ms = 0.0;
};

struct BounceStats {
  uint32_t rays = 0;                    // live paths traced
  double simtEfficiency = -1.0;         // device subgroups, counting mode only (-1: not measured)
  double virtualWarpEfficiency = -1.0;  // W = 32 from per-path traversal iterations (-1: not measured)
  double meanTraversalSteps = -1.0;     // with the virtual warp efficiency (-1: not measured)
  // Key prediction (filled when stats are requested for a bounce whose rays were keyed and sorted; -1, null
  // in JSON, on the others: there is no prediction to measure there)
  double predictionErrorMean = -1.0;    // |estimated - actual end point| / scene diagonal
  double predictionErrorMedian = -1.0;
  double cellHitRate = -1.0;            // estimated cell == actual cell
  int64_t distinctKeys = -1;
  // The trace stage's speed: rays / its GPU time (-1: no trace stage of its own, as under the megakernel or
  // a fused trace and shade). A trace that also gathers the last sort's reorder (fusion gather) includes it.
  double traceRaysPerSecond = -1.0;
  // Sort policy (wavefront with a strategy): whether the paths were sorted after this bounce, and why.
  bool sortedAfter = false;
  std::string sortReason;
};

// Mean of one per-bounce figure over the bounces that measured it (>= 0), unweighted, from bounce 1 on when
// `skipFirst` (camera rays are never sorted): the per-frame figure the bench writes (prediction_error_mean,
// cell_hit_rate, virtual_warp_efficiency_after_first) and the speed-accuracy panel plots. -1 when none did.
inline double meanOverBounces(const std::vector<BounceStats>& bounces, double BounceStats::*field, bool skipFirst) {
  double sum = 0.0;
  int n = 0;
  for (size_t b = skipFirst ? 1 : 0; b < bounces.size(); ++b)
    if (bounces[b].*field >= 0.0) sum += bounces[b].*field, ++n;
  return n ? sum / n : -1.0;
}

struct FrameStats {
  uint32_t frameIndex = 0;
  uint32_t samplesPerPixel = 0;  // accumulated so far
  double frameMs = 0.0;          // GPU time of the whole frame (first stage start to last stage end)
  double wallMs = 0.0;           // host wall time of the frame, submit to completion
  std::vector<StageTime> stages;
  std::vector<BounceStats> bounces;
  uint64_t raysTraced = 0;
  double raysPerSecond = 0.0;
  uint32_t keyBits = 0;
  uint64_t lengthCacheBytes = 0;
  double lengthCacheOccupancy = -1.0;  // detailed frames of strategies with a cache (-1, null in JSON: not measured)
  // Cache entries this frame's learning reset, summed over its bounces (RL_COUNTER_CACHE_RESETS: Gaussian
  // resets and non-finite restarts); every frame that sorts with a strategy that has a cache (-1, null in
  // JSON: no cache).
  int64_t lengthCacheResets = -1;
  uint64_t sortScratchBytes = 0;
  uint64_t pathStateBytes = 0;
  uint64_t sceneBytes = 0;
  uint64_t accelerationStructureBytes = 0;  // BLAS + TLAS of the rt tracer (compacted)
  // Set when the figures of our traversal loop (SIMT lane counts, traversal steps, virtual warp
  // efficiency) do not exist for this frame: "not available with the rt tracer". Never reported as zeros.
  std::string traversalStatsUnavailable;
  HeatmapStats heatmap;  // the heatmap shown this frame: range, unit, pixel counts, the hovered pixel
  // The frame's fixed costs (issue 36): the commands its recording issued (dispatches direct and indirect,
  // barriers, indirect-size writes), in total and per stage, and its host round trips (submissions, each
  // waited for: one for a whole frame, one per submission of a frame rendered in steps).
  CommandCounts commands;
  std::vector<StageCommands> stageCommands;
  uint32_t submissions = 0;

  // GPU time of the frame no stage scope covers (barriers between scopes, driver work): shown as its own
  // bar, so the bars always add up to frameMs.
  double stageSumMs() const {
    double ms = 0.0;
    for (const StageTime& s : stages) ms += s.ms;
    return ms;
  }
  double unattributedMs() const { return frameMs > stageSumMs() ? frameMs - stageSumMs() : 0.0; }

  // GPU time of what only measuring costs (StageRole::Instrument: the detailed statistics' passes and
  // readbacks, heatmaps), and of the frame's own work without it: a detailed frame's work time is
  // comparable with an undetailed frame's.
  double instrumentMs() const {
    double ms = 0.0;
    for (const StageTime& s : stages)
      if (const StageInfo* info = findStage(s.stage); info && info->role == StageRole::Instrument) ms += s.ms;
    return ms;
  }
  double workMs() const {
    const double instrument = instrumentMs();
    return frameMs > instrument ? frameMs - instrument : 0.0;
  }

  double stageTotal(const std::string& stage) const {
    double ms = 0.0;
    for (const StageTime& s : stages)
      if (s.stage == stage) ms += s.ms;
    return ms;
  }
};

}  // namespace raylab
