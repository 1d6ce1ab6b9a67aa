#include "app/camera_path/render_camera_path.h"

#include <algorithm>
#include <cstdio>

#include "app/camera_path/camera_path_builtin.h"
#include "app/cli_options.h"
#include "renderer/path_tracer.h"
#include "app/camera_path/camera_path_file.h"

namespace raylab {
namespace {

bool has(const std::vector<std::string>& args, const char* flag) { return std::find(args.begin(), args.end(), flag) != args.end(); }

}  // namespace

PathRender preparePathRender(const std::string& spec, const Scene& scene, const std::vector<std::string>& args,
                             bool cameraGiven, bool budgetGiven, std::optional<uint32_t> framesCap) {
  // The path sets the camera of every frame and how many frames there are.
  if (cameraGiven) throw UsageError("--camera-path moves the camera every frame: give it or --camera, not both");
  if (has(args, "--view")) throw UsageError("--camera-path moves the camera every frame: give it or --view, not both");
  if (budgetGiven)
    throw UsageError("--camera-path renders one image per path frame, not an accumulation: --time-budget does not "
                     "apply (cap the frames with --frames)");
  return pathRenderFor(spec, scene, framesCap);
}

PathRender pathRenderFor(const std::string& spec, const Scene& scene, std::optional<uint32_t> framesCap) {
  PathRender p;
  try {
    p.path = resolveCameraPath(spec, scene);
  } catch (const CameraPathError& e) {
    throw UsageError(std::string("--camera-path: ") + e.what());
  }
  p.up = sceneUp(scene);
  p.frames = framesCap ? std::min(*framesCap, p.path.frames) : p.path.frames;
  return p;
}

RenderTotals renderAlongPath(PathTracer& tracer, const PathRender& p, bool stats, uint32_t detailEvery, bool digests) {
  RenderTotals t;
  std::fprintf(stderr, "raylab: camera path %s, %u frames\n", p.path.name.c_str(), p.frames);
  for (uint32_t f = 0; f < p.frames; ++f) {
    const PathCamera camera = movePathCamera(tracer, p, f);
    nlohmann::json* frame = renderCountedFrame(tracer, f, stats, detailEvery, t, digests);
    if (!frame) continue;
    (*frame)["path_frame"] = f;
    addPathCameraJson(*frame, camera);
  }
  return t;
}

PathCamera movePathCamera(PathTracer& tracer, const PathRender& p, uint32_t f) {
  const PathCamera camera = cameraAt(p.path, f, p.up);
  tracer.setCamera(camera.view);  // restarts the accumulation, also where the camera stands still
  return camera;
}

void addPathCameraJson(nlohmann::json& frame, const PathCamera& camera) {
  frame["camera"] = {{"position", vec3Json(camera.view.position)},
                     {"target", vec3Json(camera.view.target)},
                     {"fov", glm::degrees(camera.view.yfovRadians)}};
  frame["cut"] = camera.cut;
}

nlohmann::json pathRenderJson(const PathRender& p) {
  return {{"source", p.path.name}, {"path_frames", p.path.frames}, {"keyframes", cameraKeyframesJson(p.path.keyframes)}};
}

}  // namespace raylab
