// Measures one benchmark cell on a PathTracer: warm-up frames, timed frames (median/min/max per stage,
// image error against a reference after each frame), then one untimed frame in the counting/detailed
// modes for SIMT efficiency, virtual warp efficiency and prediction accuracy.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/bench/bench_spread.h"
#include "renderer/path_tracer.h"

namespace raylab {


// A cell that replayed a camera path (app/bench/bench_path.h): its times are over the path's frames.
struct CellPath {
  std::string name;        // the path as given: a file, or "builtin:NAME"
  uint32_t frames = 0;     // path frames replayed
  double totalMs = 0.0;    // the frames' work time, summed: the path's time
  double meanMs = 0.0;     // and per frame
};

struct CellResult {
  Spread frameMs;                         // GPU time of the whole frame
  Spread wallMs;
  std::map<std::string, Spread> stageMs;  // per stage name, summed over bounces
  std::map<std::string, Spread> stageBounceMs;  // per "stage@bounce" (bounce-loop stages only)
  std::optional<Spread> traceAfterFirstMs;  // trace stage, bounces >= 1 (none: no trace stage of its own,
                                            // the megakernel and fused trace+shade)
  // The trace stage's speed, rays per second over its GPU time: camera rays (bounce 0) and the bounces after
  // (their rays over their summed trace time); a trace's speed read from one column (none: no trace stage).
  std::optional<Spread> traceCameraRaysPerSecond, traceBounceRaysPerSecond;
  std::vector<double> errorCurveMs;       // k times the median frame time, k = 1 .. timed frames
  std::vector<double> errorCurveRelMse;   // the case's relative MSE after k frames (same for every cell)
  std::optional<double> finalRelMse;      // this cell's own image after its timed frames (none: no reference)
  double raysPerSecond = 0.0;
  FrameStats detailed;                    // the counting/detailed frame
  bool detailMeasured = false;            // whether it was rendered (else `detailed` is empty: null in JSON)
  // The sort policy's decided plan after the timed frames (empty: no sort): auto's first plan after them that
  // does not measure (SortPlan::measuring), the one its counting frame renders.
  std::vector<bool> sortedAfter;
  // auto only: the frames its model had seen when the timed frames began (it had stopped exploring), and
  // whether it had (false: it still explored after kMaxSettleFrames warm-up frames; the times mix arms).
  std::optional<uint32_t> policyFramesBeforeTiming;
  bool policySettled = true;
  std::optional<CellPath> path;           // a camera path's replay (none: still frames)
  // The last timed frame's fixed costs (FrameStats::commands, submissions): the same in every timed frame
  // but under the auto policy, whose decided plan the last one renders.
  CommandCounts commands;
  uint32_t submissions = 0;
};

// What a bench run measures once, before its first cell: the device's cost of an empty dispatch and its
// barrier (renderer/vk/empty_dispatch.h; none without timestamps), which each row's fixed_cost_ms multiplies
// by its dispatches.
struct RunFacts {
  std::optional<double> emptyDispatchUs;
};
nlohmann::json toJson(const RunFacts& f);
// The estimate of a frame's fixed cost: its dispatches at the cost of an empty one (none if not measured).
std::optional<double> fixedCostMs(const CommandCounts& commands, const RunFacts& facts);

// A sort plan as the CSV's sorted_after and path_frames.jsonl write it: "Y"/"N" per bounce whose rays the plan
// sorts after, "-" for the last bounce (nothing follows it), e.g. "YNY-".
std::string sortPlanText(const std::vector<bool>& sortAfter);

// A cell's warm-up: `warmup` frames and at least half a second of them, back to back (pipelines built, the
// GPU's clocks up), before anything is timed: measureCell and a camera path's replay alike.
void warmUpFrames(PathTracer& tracer, uint32_t warmup);

// The timed frames of a cell, frame by frame, made into its CellResult times: what measureCell and a camera
// path's replay (app/bench/bench_path.cpp) both collect. `ms` is the time a frame counts as (the GPU frame time, or
// the work time along a path); the Instrument stages (the detail passes) are left out of the stages.
struct TimedFrames {
  std::vector<double> frame, wall, traceLater, cameraRate, bounceRate;
  std::map<std::string, std::vector<double>> stages, bounceStages;
  bool tracedLater = false;  // some frame had a trace stage of bounce >= 1
  double total = 0.0;
  uint64_t rays = 0;
  CommandCounts commands;  // the last frame's
  uint32_t submissions = 0;

  void add(const FrameStats& st, double ms);
  void fillInto(CellResult& r) const;
};

// The most frames a cell of the auto policy runs after its warm-up waiting for its plan to stop exploring (it
// needs SortPolicyModel::kColdFrames + 2 * kMinSamples = 6 frames from a reset).
inline constexpr uint32_t kMaxSettleFrames = 256;

// What a case's scene costs before any frame: its size, its BVH (what the trace stage reads: nodes and the
// triangles in BVH order) and the host time to make the scene and to set the tracer up (BVH build, uploads,
// pipelines). The scene-scale sweep charts ratios against these.
struct SceneFacts {
  uint64_t triangles = 0;
  uint64_t bvhNodes = 0;
  uint64_t bvhBytes = 0;    // nodes + BVH-order triangles
  // The wide BVH collapsed from the binary one (Settings::bvh wide), counted alike: nodes, leaf records and
  // the same BVH-order triangles.
  uint64_t wideBvhNodes = 0;
  uint64_t wideBvhBytes = 0;
  uint64_t sceneBytes = 0;  // every scene buffer on the device
  double bvhBuildMs = 0.0;
  // The tree with spatial splits (BvhLayout::Sbvh): its leaf entries and build time.
  uint64_t sbvhReferences = 0;
  double sbvhBuildMs = 0.0;
  double sceneLoadMs = 0.0;
  double tracerSetupMs = 0.0;
};
SceneFacts sceneFactsOf(const GpuSceneData& scene, double sceneLoadMs, double tracerSetupMs);
nlohmann::json toJson(const SceneFacts& f);

// The timed frames run back to back with no readback between them: host gaps let a GPU drop its clocks,
// which was seen to slow later cells of a sweep two- to fourfold on an H100. Warm-up lasts at least
// `warmup` frames and half a second, and with the auto policy until its plan stops exploring (it is timed
// once it has decided, not while it measures its arms; issue 34). `errorCurve` is the case's relative MSE after k frames: sorting never
// changes the image (tested bit for bit), so every cell shares it and only its time axis differs.
CellResult measureCell(PathTracer& tracer, const Settings& settings, uint32_t warmup, uint32_t timed,
                       const std::vector<glm::vec3>& reference, const std::vector<double>& errorCurve,
                       bool detailFrame);

// Relative MSE against `reference` after each of `frames` frames of the unsorted wavefront (untimed).
std::vector<double> measureErrorCurve(PathTracer& tracer, const Settings& settings, uint32_t frames,
                                      const std::vector<glm::vec3>& reference);

nlohmann::json toJson(const CellResult& r);

}  // namespace raylab
