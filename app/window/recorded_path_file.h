// Saving a camera path recorded in the window: NAME.path.json, the path in the form `--camera-path` reads
// (app/camera_path/camera_path_file.h), and NAME.json beside it, a sidecar as screenshots have (app/sidecar.h: the
// settings, scene, device, revision and the last frame's statistics, the first keyframe as its camera),
// with "camera_path" naming the path file and "replay" the command that renders it:
//   raylab render --settings NAME.json --camera-path NAME.path.json
#pragma once

#include <string>

#include "app/camera_path/camera_path.h"
#include "app/sidecar.h"

namespace raylab {

// Writes both files into `dir` (created if missing) through writeFileChecked, the sidecar last; when it
// fails the path file is removed again (a path without its sidecar does not say which scene it belongs
// to). Returns the path file's path. Throws std::runtime_error (WriteError when a write failed).
std::string writeRecordedPath(const std::string& dir, const std::string& name, const CameraPath& path,
                              SidecarContent content);

}  // namespace raylab
