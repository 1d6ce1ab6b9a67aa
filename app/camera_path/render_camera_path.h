// `raylab render --camera-path FILE|builtin:NAME` (issue 37): one frame per path frame, the camera moved
// before each with PathTracer::setCamera, as the window moves it. A camera move restarts the accumulation
// (SettingsChange::cameraMove), so every path frame is a fresh image of --spp samples (and its frame index,
// hence its random numbers, restart at 0); the key grid moves with the camera when it is clamped to it. What
// the length caches learned and the auto sort policy's measured costs are kept across frames and across
// cuts alike: the renderer is not told of cuts, which is what a moving-camera study measures (how learned
// state copes with a jump to another room).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/camera_path/camera_path.h"
#include "app/render_totals.h"

namespace raylab {

class PathTracer;

struct PathRender {
  CameraPath path;
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  uint32_t frames = 0;  // the path's frames, capped by --frames
};

// Resolves `spec` for `scene` and checks it against the other flags: --camera, --view and --time-budget
// make no sense with it (UsageError, exit 2); a bad path is a UsageError naming it. `framesCap`: --frames
// when given.
PathRender preparePathRender(const std::string& spec, const Scene& scene, const std::vector<std::string>& args,
                             bool cameraGiven, bool budgetGiven, std::optional<uint32_t> framesCap);

// The path `spec` names for `scene` (a bad one: UsageError naming it), `framesCap` frames at most: what
// preparePathRender checks besides the flags, and what `raylab bench --camera-path` resolves per case.
PathRender pathRenderFor(const std::string& spec, const Scene& scene, std::optional<uint32_t> framesCap);

// Moves the tracer's camera to path frame `f` (restarting the accumulation, as a camera move in the window
// does) and returns that camera: every command that replays a path moves it through here.
PathCamera movePathCamera(PathTracer& tracer, const PathRender& p, uint32_t f);
// A path frame's camera and cut flag as the stats and the bench's path_frames.jsonl record them:
// "camera" (position, target, fov in degrees) and "cut", added to `frame`.
void addPathCameraJson(nlohmann::json& frame, const PathCamera& camera);

// Renders the path's frames; with `stats`, one JSON frame each: the frame's stats, "path_frame", "camera"
// (position, target, fov in degrees) and "cut". Detailed figures every `detailEvery`th frame (0: none);
// `digests`: each frame's radiance digest too (--frame-digests).
RenderTotals renderAlongPath(PathTracer& tracer, const PathRender& p, bool stats, uint32_t detailEvery,
                             bool digests = false);

// The path as the --stats file records it: its name, frames rendered and keyframes.
nlohmann::json pathRenderJson(const PathRender& p);

}  // namespace raylab
