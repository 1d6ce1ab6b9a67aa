// Recording a camera path in the window (issue 37): one keyframe per UI frame while recording, the camera as
// the user flies it (position, target, vertical field of view), numbered from 0. Every UI frame is kept,
// still ones too, so a replay (`raylab render --camera-path FILE`, one image per keyframe) moves at the pace
// the camera was flown at, counted in UI frames. No window types: the CPU tests check it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "app/camera_path/camera_path.h"
#include "scenes/scene.h"

namespace raylab {

// A keyframe that is `view` exactly at `frame` (its name and up vector are not part of a keyframe).
CameraKeyframe keyframeOf(const Viewpoint& view, uint32_t frame);

class CameraPathRecorder {
 public:
  // Starts a new recording (what an earlier one kept is dropped) in a scene whose paths use `up`
  // (sceneUp: what a replay turns the camera about).
  void start(const glm::vec3& up);
  // The camera of this UI frame; ignored while not recording.
  void add(const Viewpoint& view);
  bool recording() const { return recording_; }
  uint32_t frames() const { return uint32_t(keyframes_.size()); }
  // Ends the recording: the path of its keyframes named `name`, checked as a path file is (checkCameraPath:
  // a CameraPathError says why it could not be replayed), or nothing when no frame was recorded.
  std::optional<CameraPath> stop(const std::string& name);

 private:
  bool recording_ = false;
  glm::vec3 up_{0.0f, 1.0f, 0.0f};
  std::vector<CameraKeyframe> keyframes_;
};

}  // namespace raylab
