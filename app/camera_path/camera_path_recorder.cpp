#include "app/camera_path/camera_path_recorder.h"

#include <glm/trigonometric.hpp>

namespace raylab {

CameraKeyframe keyframeOf(const Viewpoint& view, uint32_t frame) {
  CameraKeyframe k;
  k.frame = frame;
  k.position = view.position;
  k.target = view.target;
  k.fovDegrees = glm::degrees(view.yfovRadians);
  return k;
}

void CameraPathRecorder::start(const glm::vec3& up) {
  up_ = up;
  keyframes_.clear();
  recording_ = true;
}

void CameraPathRecorder::add(const Viewpoint& view) {
  if (recording_) keyframes_.push_back(keyframeOf(view, frames()));
}

std::optional<CameraPath> CameraPathRecorder::stop(const std::string& name) {
  recording_ = false;
  if (keyframes_.empty()) return std::nullopt;
  CameraPath path;
  path.name = name;
  path.keyframes = std::move(keyframes_);
  keyframes_.clear();
  path.frames = uint32_t(path.keyframes.size());
  checkCameraPath(path, up_);
  return path;
}

}  // namespace raylab
