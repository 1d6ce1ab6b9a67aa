// A sweep's cases (bench --cases, study SCENE@VIEW) checked whole before anything renders: every named
// viewpoint must exist in its scene. A bad one is a usage error (exit 2), as the help promises, not a sweep
// whose every cell fails (exit 1, empty results).
#pragma once

#include <string>
#include <vector>

namespace raylab {

// Throws UsageError ("temple@hal: no viewpoint 'hal' in temple (did you mean hall?); it has: ...") when
// `view` is not empty and not a viewpoint of `scene`, or SceneLoadError for an unusable file. Loads the
// scene to read its viewpoints (a family's smallest member: its viewpoints do not depend on the size).
void checkCaseView(const std::string& scene, const std::string& view);

// Throws UsageError ("--camera-path: ...") when `pathSpec` names no usable camera path for `scene` (an unknown
// built-in, a file that does not parse), loading the scene as checkCaseView does. Returns the path's frames.
uint32_t checkCasePath(const std::string& scene, const std::string& pathSpec);

// The built-in camera paths of `scene` as --camera-path values ("builtin:orbit", ...), loading it as
// checkCaseView does; empty for a scene without one.
std::vector<std::string> caseBuiltinPaths(const std::string& scene);

}  // namespace raylab
