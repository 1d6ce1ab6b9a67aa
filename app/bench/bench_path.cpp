#include "app/bench/bench_path.h"

#include <map>

#include "app/bench/bench_spread.h"
#include "renderer/stages.h"

namespace raylab {
namespace {

nlohmann::json optional(double v) { return v < 0.0 ? nlohmann::json(nullptr) : nlohmann::json(v); }

// The mean over the path's detailed frames of each bounce's accuracy and coherence figures (where measured):
// what the CSV's prediction_error_mean, cell_hit_rate and warp-efficiency columns show for a path cell.
struct DetailMeans {
  std::map<size_t, std::pair<double, int>> error, errorMedian, hits, vwe, steps;
  std::pair<double, int> occupancy{0.0, 0};
  static void add(std::pair<double, int>& m, double v) {
    if (v >= 0.0) m.first += v, ++m.second;
  }
  void add(const FrameStats& st) {
    for (size_t b = 0; b < st.bounces.size(); ++b) {
      add(error[b], st.bounces[b].predictionErrorMean);
      add(errorMedian[b], st.bounces[b].predictionErrorMedian);
      add(hits[b], st.bounces[b].cellHitRate);
      add(vwe[b], st.bounces[b].virtualWarpEfficiency);
      add(steps[b], st.bounces[b].meanTraversalSteps);
    }
    add(occupancy, st.lengthCacheOccupancy);
  }
  static double mean(const std::pair<double, int>& m) { return m.second ? m.first / m.second : -1.0; }
  void applyTo(FrameStats& st) {
    for (size_t b = 0; b < st.bounces.size(); ++b) {
      st.bounces[b].predictionErrorMean = mean(error[b]);
      st.bounces[b].predictionErrorMedian = mean(errorMedian[b]);
      st.bounces[b].cellHitRate = mean(hits[b]);
      st.bounces[b].virtualWarpEfficiency = mean(vwe[b]);
      st.bounces[b].meanTraversalSteps = mean(steps[b]);
      st.bounces[b].simtEfficiency = -1.0;  // no counting pass along a path
    }
    st.lengthCacheOccupancy = mean(occupancy);
  }
};

}  // namespace

nlohmann::json pathFrameJson(uint32_t f, const PathCamera& camera, const FrameStats& st, const SortPlan& plan,
                             bool learningRestarted, bool detailed) {
  nlohmann::json frame = {{"path_frame", f}};
  addPathCameraJson(frame, camera);
  nlohmann::json stages = nlohmann::json::object();
  for (const StageTime& s : st.stages) stages[s.stage] = stages.value(s.stage, 0.0) + s.ms;
  nlohmann::json rays = nlohmann::json::array(), error = nlohmann::json::array(), hits = nlohmann::json::array();
  for (const BounceStats& b : st.bounces) {
    rays.push_back(b.rays);
    error.push_back(optional(b.predictionErrorMean));
    hits.push_back(optional(b.cellHitRate));
  }
  frame["frame_ms"] = st.frameMs;
  frame["work_ms"] = st.workMs();
  frame["wall_ms"] = st.wallMs;
  frame["stage_ms"] = stages;
  frame["rays"] = rays;
  frame["prediction_error"] = error;
  frame["cell_hit_rate"] = hits;
  frame["prediction_error_mean"] = optional(meanOverBounces(st.bounces, &BounceStats::predictionErrorMean, true));
  frame["cell_hit_rate_mean"] = optional(meanOverBounces(st.bounces, &BounceStats::cellHitRate, true));
  frame["length_cache_occupancy"] = optional(st.lengthCacheOccupancy);
  frame["length_cache_resets"] = st.lengthCacheResets < 0 ? nlohmann::json(nullptr) : nlohmann::json(st.lengthCacheResets);
  frame["learning_restarted"] = learningRestarted;
  frame["sorted_after"] = sortPlanText(plan.sortAfter);
  frame["measuring"] = plan.measuring;
  frame["detailed"] = detailed;
  return frame;
}

PathCellResult measurePathCell(PathTracer& tracer, const Settings& settings, const PathRender& path, uint32_t warmup,
                               bool detailed) {
  PathCellResult out;
  CellResult& r = out.cell;
  tracer.setDetailedStats(false);
  tracer.applySettings(settings);
  // Warm-up (pipelines, clocks) at the path's first camera, then the learned state is dropped: the replay
  // starts as `raylab render --camera-path` does on a fresh tracer, so every cell and round replays alike.
  movePathCamera(tracer, path, 0);
  warmUpFrames(tracer, warmup);
  tracer.restartLearning();
  tracer.sortPolicy().reset();
  tracer.setDetailedStats(detailed);

  TimedFrames timed;
  DetailMeans means;
  for (uint32_t f = 0; f < path.frames; ++f) {
    const PathCamera camera = movePathCamera(tracer, path, f);
    const FrameStats& st = tracer.renderFrame();
    out.frames.push_back(pathFrameJson(f, camera, st, tracer.sortPlan(), f == 0, detailed));
    timed.add(st, st.workMs());
    if (detailed) means.add(st);
    if (f + 1 == path.frames) r.detailed = st;
  }
  tracer.setDetailedStats(false);

  timed.fillInto(r);
  if (settings.sorts()) r.sortedAfter = tracer.sortPlan().sortAfter;
  r.detailMeasured = detailed && path.frames > 0;
  if (r.detailMeasured) means.applyTo(r.detailed);
  else r.detailed = FrameStats{};
  r.path = CellPath{path.path.name, path.frames, timed.total, path.frames ? timed.total / path.frames : 0.0};
  return out;
}

}  // namespace raylab
