#include "app/camera_path/camera_path_file.h"

namespace raylab {

nlohmann::json vec3Json(const glm::vec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); }

nlohmann::json cameraKeyframesJson(const std::vector<CameraKeyframe>& keyframes) {
  nlohmann::json out = nlohmann::json::array();
  // Floats are written as the doubles they widen to, which read back to the same floats: a saved path
  // replays the cameras it recorded bit for bit.
  for (const CameraKeyframe& k : keyframes)
    out.push_back({{"frame", k.frame}, {"position", vec3Json(k.position)}, {"target", vec3Json(k.target)},
                   {"fov", k.fovDegrees}, {"cut", k.cut}});
  return out;
}

nlohmann::json cameraPathFileJson(const CameraPath& path) {
  return {{"frames", path.frames}, {"keyframes", cameraKeyframesJson(path.keyframes)}};
}

std::string cameraPathFileText(const CameraPath& path) {
  const nlohmann::json j = cameraPathFileJson(path);
  std::string text = "{\"frames\": " + j.at("frames").dump() + ",\n \"keyframes\": [";
  const nlohmann::json& keyframes = j.at("keyframes");
  for (size_t i = 0; i < keyframes.size(); ++i) text += (i ? ",\n  " : "\n  ") + keyframes[i].dump();
  return text + "\n ]}\n";
}

}  // namespace raylab
