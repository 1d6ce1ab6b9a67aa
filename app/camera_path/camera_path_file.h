// The JSON form of a camera path (app/camera_path.h documents it; parseCameraPath reads it): written where a
// path is saved (the window's recording) and where it is echoed (the --stats file's "camera_path"), so the
// form is spelled once for writing as it is once for reading.
#pragma once

#include <nlohmann/json.hpp>

#include "app/camera_path/camera_path.h"

namespace raylab {

// A vector as the path file writes it: [x, y, z].
nlohmann::json vec3Json(const glm::vec3& v);
// The keyframes as the file's "keyframes" array: frame, position, target, fov (degrees) and cut.
nlohmann::json cameraKeyframesJson(const std::vector<CameraKeyframe>& keyframes);
// The whole file: {"frames": N, "keyframes": [...]}; parseCameraPath(dump) gives the path back.
nlohmann::json cameraPathFileJson(const CameraPath& path);
// That JSON as a file's text, one keyframe a line (a recording has one per UI frame: a line each reads and
// diffs well, where an indented dump spends 20 lines on each).
std::string cameraPathFileText(const CameraPath& path);

}  // namespace raylab
