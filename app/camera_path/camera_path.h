// Camera paths (issue 37): a moving camera for `raylab render --camera-path`, as keyframes that are
// interpolated per frame. Pure math and parsing, no device, so the CPU tests check it.
//
// A path is a list of keyframes (frame number, position, target, vertical field of view). Between two
// keyframes of one segment the camera moves on a centripetal Catmull-Rom spline through the keyframe
// positions (centripetal: no cusps or loops where keyframes are unevenly spaced), its look direction turns
// by slerp (constant angular speed, unit length kept), the distance to the target and the field of view
// change linearly. A keyframe flagged `cut` starts a new segment: nothing is interpolated across it; the
// camera holds the last keyframe of a segment until the cut's frame, then jumps.
//
// File form (JSON):
//   {"frames": 240,                       optional; default: the last keyframe's frame + 1
//    "keyframes": [{"frame": 0, "position": [x, y, z], "target": [x, y, z], "fov": 45, "cut": false}, ...]}
// fov is vertical, in degrees; cut is optional (default false).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/scene.h"

namespace raylab {

// A path that cannot be used; the message names the keyframe (by index, from 0) and the problem. The
// render command turns it into a usage error (exit 2).
struct CameraPathError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct CameraKeyframe {
  uint32_t frame = 0;
  glm::vec3 position{0.0f};
  glm::vec3 target{0.0f, 0.0f, -1.0f};
  float fovDegrees = 45.0f;
  bool cut = false;  // starts a new segment: a jump from the previous keyframe, no interpolation across it
};

struct CameraPath {
  std::string name;  // the file, or "builtin:NAME"
  std::vector<CameraKeyframe> keyframes;
  uint32_t frames = 0;  // how many frames the path renders
};

// The camera of one frame of a path.
struct PathCamera {
  Viewpoint view;
  bool cut = false;  // this frame is a cut's keyframe: the camera jumped here from the frame before
};

// The limits a keyframe's field of view must respect (those of the --camera text form).
inline constexpr float kPathMinFovDegrees = 0.5f, kPathMaxFovDegrees = 179.5f;
// The most frames a path may have: SettingLimits::kMaxFrames, checked where the path is read.

// Checks the keyframes and frame count (at least one keyframe, increasing frame numbers, finite values,
// position != target, field of view within limits, no cut on the first keyframe, a view that never turns
// through straight up or down along `up`, where the camera would have no horizon); throws CameraPathError.
void checkCameraPath(const CameraPath& path, const glm::vec3& up);

// The camera at `frame` (any frame; before the first keyframe it is the first's, after the last the last's).
// At a keyframe's frame it is the keyframe exactly. `up` is the scene's up vector.
PathCamera cameraAt(const CameraPath& path, uint32_t frame, const glm::vec3& up);

// Parses the JSON form (see above); `source` names the input in messages. Throws CameraPathError for
// JSON syntax (with nlohmann's line and column), missing or unknown fields, and what checkCameraPath checks.
CameraPath parseCameraPath(const std::string& text, const std::string& source, const glm::vec3& up);
CameraPath loadCameraPath(const std::string& file, const glm::vec3& up);

// Spherical interpolation of two unit directions (t in [0, 1]); antiparallel ones turn about `up`'s
// perpendicular. The result has unit length.
glm::vec3 slerpDirection(const glm::vec3& a, const glm::vec3& b, float t, const glm::vec3& up);

}  // namespace raylab
