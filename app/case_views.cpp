#include "app/case_views.h"

#include <stdexcept>
#include <vector>

#include "app/cli_options.h"
#include "app/command_errors.h"
#include "scenes/clutter.h"
#include "scenes/scene_library.h"
#include "scenes/temple_detail.h"

namespace raylab {

void checkCaseView(const std::string& scene, const std::string& view) {
  if (view.empty()) return;
  // Scene names are checked before this (bench_sweep.cpp's checkCaseScene): only the view is new here.
  const std::string load = isTempleDetailName(scene) ? std::string("temple")
                           : isClutterName(scene)    ? std::string(kClutterName) + ":" + std::to_string(kClutterMinTriangles)
                                                     : scene;
  Scene s;
  try {
    s = loadSceneByName(load);
  } catch (const std::invalid_argument& e) {
    throw UsageError(scene + "@" + view + ": " + e.what());
  }
  if (s.findViewpoint(view)) return;
  std::vector<std::string> names;
  for (const Viewpoint& v : s.viewpoints) names.push_back(v.name);
  const std::string near = nearestName(view, names);
  throw UsageError(scene + "@" + view + ": no viewpoint '" + view + "' in " + scene +
                   (near.empty() ? "" : " (did you mean " + near + "?)") + "; it has: " + s.viewpointList());
}

}  // namespace raylab
