// `raylab bench --camera-path FILE|builtin:NAME` (issue 37): the path as a case axis. Every cell of a case
// replays the path instead of timing still frames: after its warm-up (at the path's first camera) the
// learned lengths and the sort policy's costs start from nothing, as in `raylab render --camera-path` on a
// fresh tracer, and each path frame is one fresh frame, the camera moved by movePathCamera (what render
// does: SettingsChange::cameraMove). The cell's times are over the path's frames; each path frame's
// figures are one line of path_frames.jsonl.
#pragma once

#include <cstdint>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/bench/bench_measure.h"
#include "app/camera_path/render_camera_path.h"

namespace raylab {

struct PathCellResult {
  CellResult cell;                    // times over the path's frames; path set
  std::vector<nlohmann::json> frames;  // one per path frame (pathFrameJson), in path order
};

// Replays `path` with `settings`: `warmup` frames (and half a second) at its first camera, then every path
// frame. With `detailed` every path frame carries the detail passes (prediction error, cell hits, cache
// occupancy), timed as the counters stage outside the frame's work: a path cell's times are work times
// (FrameStats::workMs), so they hold with and without them. No SIMT counting, no reference image.
PathCellResult measurePathCell(PathTracer& tracer, const Settings& settings, const PathRender& path, uint32_t warmup,
                               bool detailed);

// One path frame's figures: "path_frame", "cut", "camera", "frame_ms" (GPU), "work_ms", "wall_ms",
// "stage_ms" {stage: ms summed over bounces}, per bounce "rays", "prediction_error", "cell_hit_rate"
// (null where not measured), their means over bounces >= 1 ("prediction_error_mean", "cell_hit_rate_mean"),
// "length_cache_occupancy" (null unless detailed), "length_cache_resets" (entries this frame's learning
// reset: FrameStats::lengthCacheResets, every frame; null without a cache), "learning_restarted" (the
// length caches and the policy's costs started from nothing before this frame: the replay's first frame; a
// cut restarts nothing),
// "sorted_after" ("YN-": the plan), "measuring" (auto's plan measured an arm) and "detailed".
nlohmann::json pathFrameJson(uint32_t f, const PathCamera& camera, const FrameStats& st, const SortPlan& plan,
                             bool learningRestarted, bool detailed);

}  // namespace raylab
