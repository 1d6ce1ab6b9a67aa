// What every mode does first: resolve the scene and viewpoint named in Settings, and the Vulkan context
// options (the RAYLAB_VALIDATE environment variable turns validation on, as the tests do: 1 or sync, gpu-av).
#pragma once

#include "app/cli_options.h"
#include "app/command_errors.h"  // the exit codes its callers return
#include "renderer/vk/vk_context.h"
#include "scenes/scene.h"

namespace raylab {

struct LoadedScene {
  Scene scene;
  Viewpoint view;
};

// Throws SceneLoadError for unusable files (exit 3) and UsageError for unknown names (exit 2).
LoadedScene loadSceneForSettings(const Settings& settings);
const Viewpoint& resolveViewpoint(const Scene& scene, const std::string& name);
ContextOptions contextOptionsFor(const CommonOptions& options);
// Whether the device's compute queue has timestamp queries, which the timing commands need; says so on
// stderr as "COMMAND: DEVICE has no timestamp queries ..." when it has not.
bool deviceTimesCompute(const VulkanContext& ctx, const std::string& command);

}  // namespace raylab
