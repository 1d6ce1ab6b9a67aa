#include "app/scene_setup.h"

#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "scenes/scene_library.h"

namespace raylab {

const Viewpoint& resolveViewpoint(const Scene& scene, const std::string& name) {
  if (scene.viewpoints.empty()) throw SceneLoadError(scene.name + ": the scene has no viewpoint");
  if (name.empty()) return scene.viewpoints.front();
  if (const Viewpoint* v = scene.findViewpoint(name)) return *v;
  throw UsageError("--view '" + name + "' is not a viewpoint of " + scene.name + "; it has: " + scene.viewpointList());
}

LoadedScene loadSceneForSettings(const Settings& settings) {
  LoadedScene loaded;
  try {
    loaded.scene = loadSceneByName(settings.scene, settings.clutterSeed);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  if (loaded.scene.triangles.empty()) throw SceneLoadError(settings.scene + ": the scene has no triangles");
  loaded.view = resolveViewpoint(loaded.scene, settings.view);
  return loaded;
}

ContextOptions contextOptionsFor(const CommonOptions& options) {
  ContextOptions c;
  c.deviceName = options.device;
  // A flag wins over the environment (RAYLAB_VALIDATE, which ctest sets for every GPU test).
  ValidationMode env = ValidationMode::Off;
  try {
    env = validationModeFromEnvironment();
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  c.validation = options.validation != ValidationMode::Off ? options.validation : env;
  return c;
}

bool deviceTimesCompute(const VulkanContext& ctx, const std::string& command) {
  const DeviceInfo& dev = ctx.info();
  if (dev.timestamps && dev.timestampPeriodNs > 0) return true;
  std::fprintf(stderr, "%s: %s has no timestamp queries on its compute queue\n", command.c_str(), dev.name.c_str());
  return false;
}

}  // namespace raylab
