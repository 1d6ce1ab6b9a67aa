// The built-in camera paths, `--camera-path builtin:NAME`: `orbit` for every scene (from its bounds), and
// for the temple `walk` (the alley into the hall) and `cut` (hall and openings alternating), for the clutter
// room its own `orbit`, `pan` (along the shelves) and `cut` (shelves and floor alternating). They are built
// from the scene's viewpoints and bounds; the README's "Camera paths" lists them.
#pragma once

#include <string>
#include <vector>

#include "app/camera_path/camera_path.h"
#include "scenes/scene.h"

namespace raylab {

inline constexpr const char* kBuiltinPathPrefix = "builtin:";
// How many frames every built-in path has, and how long each shot of a `cut` path lasts.
inline constexpr uint32_t kBuiltinPathFrames = 240, kBuiltinShotFrames = 30;

// The names `scene` has built-in paths for, `orbit` first.
std::vector<std::string> builtinCameraPathNames(const Scene& scene);
// The path `name` (without the prefix) for `scene`; CameraPathError listing the names for an unknown one.
CameraPath builtinCameraPath(const Scene& scene, const std::string& name);
// `--camera-path`'s value: "builtin:NAME" (builtin:list lists them, as an error) or a JSON file. The path's
// up vector is that of the scene's first viewpoint. Throws CameraPathError.
CameraPath resolveCameraPath(const std::string& spec, const Scene& scene);
// The up vector paths of `scene` use.
glm::vec3 sceneUp(const Scene& scene);

}  // namespace raylab
