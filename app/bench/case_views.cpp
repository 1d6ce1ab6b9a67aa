#include "app/bench/case_views.h"

#include <stdexcept>
#include <vector>

#include "app/camera_path/camera_path_builtin.h"
#include "app/cli_options.h"
#include "app/command_errors.h"
#include "scenes/clutter.h"
#include "scenes/scene_library.h"
#include "scenes/temple_detail.h"

namespace raylab {

namespace {

// The scene a case's checks read: a family's smallest member (its viewpoints do not depend on the size).
// Scene names are checked before this (bench_sweep.cpp's checkCaseScene). `what` names the case in errors.
Scene loadForChecks(const std::string& scene, const std::string& what) {
  const std::string load = isTempleDetailName(scene) ? std::string("temple")
                           : isClutterName(scene)    ? std::string(kClutterName) + ":" + std::to_string(kClutterMinTriangles)
                                                     : scene;
  try {
    return loadSceneByName(load);
  } catch (const std::invalid_argument& e) {
    throw UsageError(what + ": " + e.what());
  }
}

}  // namespace

uint32_t checkCasePath(const std::string& scene, const std::string& pathSpec) {
  const Scene s = loadForChecks(scene, scene);
  try {
    return resolveCameraPath(pathSpec, s).frames;
  } catch (const CameraPathError& e) {
    throw UsageError(std::string("--camera-path: ") + e.what());
  }
}

std::vector<std::string> caseBuiltinPaths(const std::string& scene) {
  std::vector<std::string> specs;
  for (const std::string& name : builtinCameraPathNames(loadForChecks(scene, scene)))
    specs.push_back(kBuiltinPathPrefix + name);
  return specs;
}

void checkCaseView(const std::string& scene, const std::string& view) {
  if (view.empty()) return;
  const Scene s = loadForChecks(scene, scene + "@" + view);
  if (s.findViewpoint(view)) return;
  std::vector<std::string> names;
  for (const Viewpoint& v : s.viewpoints) names.push_back(v.name);
  const std::string near = nearestName(view, names);
  throw UsageError(scene + "@" + view + ": no viewpoint '" + view + "' in " + scene +
                   (near.empty() ? "" : " (did you mean " + near + "?)") + "; it has: " + s.viewpointList());
}

}  // namespace raylab
