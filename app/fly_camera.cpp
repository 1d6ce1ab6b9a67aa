#include "app/fly_camera.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/quaternion.hpp>

namespace raylab {
namespace {

glm::vec3 worldUp(const Viewpoint& v) {
  return glm::length(v.up) > 0.0f ? glm::normalize(v.up) : glm::vec3(0.0f, 1.0f, 0.0f);
}

glm::vec3 rotate(const glm::vec3& v, float radians, const glm::vec3& axis) {
  return glm::angleAxis(radians, axis) * v;
}

// The camera's right vector; any horizontal vector when looking along the up axis.
glm::vec3 rightOf(const glm::vec3& forward, const glm::vec3& up) {
  glm::vec3 r = glm::cross(forward, up);
  if (glm::length(r) < 1e-6f) r = glm::cross(forward, std::abs(up.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1));
  return glm::normalize(r);
}

// How close to straight up or down the camera may look (cosine of the angle to the up axis).
constexpr float kMinPoleCos = 0.995f;

}  // namespace

void FlyCamera::reset(const Viewpoint& v, float speed) {
  base_ = v;
  position_ = v.position;
  glm::vec3 d = v.target - v.position;
  focus_ = std::max(glm::length(d), 1e-3f);
  forward_ = glm::length(d) > 1e-9f ? glm::normalize(d) : glm::vec3(0.0f, 0.0f, -1.0f);
  speed_ = speed;
  pivot_ = v.target;
  target_ = v.target;
}

Viewpoint FlyCamera::viewpoint() const {
  Viewpoint v = base_;
  v.position = position_;
  v.target = target_;
  return v;
}

void FlyCamera::setOrbit(bool on, const glm::vec3& pivot) {
  orbit_ = on;
  if (!on) return;
  pivot_ = pivot;
  glm::vec3 d = pivot_ - position_;
  if (glm::length(d) < 1e-6f) {  // standing on the pivot: step back along the view direction
    position_ = pivot_ - forward_ * focus_;
    d = pivot_ - position_;
  }
  focus_ = glm::length(d);
  forward_ = glm::normalize(d);
  target_ = pivot_;
}

// Yaw turns around the world up axis; pitch changes the elevation above the horizon, clamped short of the
// poles (where "right" is undefined), so even a huge mouse jump cannot flip the camera over.
void FlyCamera::turn(float yaw, float pitch) {
  const glm::vec3 up = worldUp(base_);
  const glm::vec3 f = rotate(forward_, yaw, up);
  const glm::vec3 horizontal = glm::normalize(glm::cross(up, rightOf(f, up)));
  const float maxElevation = glm::half_pi<float>() - std::acos(kMinPoleCos);
  float elevation = std::asin(std::clamp(glm::dot(f, up), -1.0f, 1.0f));
  elevation = std::clamp(elevation + pitch, -maxElevation, maxElevation);
  forward_ = glm::normalize(horizontal * std::cos(elevation) + up * std::sin(elevation));
}

bool FlyCamera::update(const CameraInput& in) {
  return orbit_ ? updateOrbit(in) : updateFly(in);
}

bool FlyCamera::updateFly(const CameraInput& in) {
  const glm::vec3 before = position_, forwardBefore = forward_;
  if (in.look != glm::vec2(0.0f)) turn(-in.look.x * kLookRadiansPerPixel, -in.look.y * kLookRadiansPerPixel);
  const glm::vec3 up = worldUp(base_);
  const glm::vec3 right = rightOf(forward_, up);
  float step = speed_ * in.seconds * (in.fast ? kFastFactor : 1.0f);
  position_ += (right * in.move.x + up * in.move.y + forward_ * in.move.z) * step;
  if (in.zoom != 0.0f) position_ += forward_ * (in.zoom * 0.1f * focus_);
  if (position_ == before && forward_ == forwardBefore) return false;
  target_ = position_ + forward_ * focus_;
  return true;
}

// Orbit: looking turns the camera around the pivot, A/D and Q/E do the same from the keyboard, W/S and
// the scroll wheel change the distance (multiplicatively, so zooming feels the same at every scale).
bool FlyCamera::updateOrbit(const CameraInput& in) {
  const glm::vec3 before = position_;
  float keyTurn = in.seconds * (in.fast ? kFastFactor : 1.0f) * 1.5f;  // radians per second
  float yaw = -in.look.x * kLookRadiansPerPixel - in.move.x * keyTurn;
  float pitch = -in.look.y * kLookRadiansPerPixel + in.move.y * keyTurn;
  float zoomSteps = in.zoom + in.move.z * in.seconds * (in.fast ? kFastFactor : 1.0f) * 2.0f;
  if (yaw == 0.0f && pitch == 0.0f && zoomSteps == 0.0f) return false;
  turn(yaw, pitch);
  focus_ = std::max(focus_ * std::exp(-0.1f * zoomSteps), 1e-3f);
  position_ = pivot_ - forward_ * focus_;
  return position_ != before;
}

std::string cameraToText(const Viewpoint& v) {
  char text[256];
  std::snprintf(text, sizeof(text), "camera %.9g %.9g %.9g %.9g %.9g %.9g fov %.9g", v.position.x, v.position.y,
                v.position.z, v.target.x, v.target.y, v.target.z, glm::degrees(v.yfovRadians));
  return text;
}

namespace {
// A coordinate for reading, not for copying: three decimals, trailing zeros dropped, a tiny value (a float
// that drifted off zero, 1.05e-05) shown as 0.
std::string rounded(float value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.3f", value);
  std::string s = text;
  s.erase(s.find_last_not_of('0') + 1);
  if (s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}
}  // namespace

std::string cameraToShortText(const Viewpoint& v) {
  return "camera " + rounded(v.position.x) + " " + rounded(v.position.y) + " " + rounded(v.position.z) + " " +
         rounded(v.target.x) + " " + rounded(v.target.y) + " " + rounded(v.target.z) + " fov " +
         rounded(glm::degrees(v.yfovRadians));
}

std::string viewpointLabel(const Viewpoint& v) {
  if (!v.name.empty()) return v.name;
  return "camera at (" + rounded(v.position.x) + ", " + rounded(v.position.y) + ", " + rounded(v.position.z) + ")";
}

std::optional<Viewpoint> cameraFromText(const std::string& text, const Viewpoint& base, std::string* error) {
  std::istringstream in(text);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  if (!words.empty() && words[0] == "camera") words.erase(words.begin());
  std::optional<float> fov;
  if (words.size() == 8 && words[6] == "fov") {
    fov = 0.0f;
    words.erase(words.begin() + 6);
  }
  auto fail = [&](const std::string& why) -> std::optional<Viewpoint> {
    if (error) *error = why;
    return std::nullopt;
  };
  if (words.size() != 6 && !(fov && words.size() == 7))
    return fail("a camera is 'camera X Y Z TX TY TZ [fov DEGREES]', got '" + text + "'");
  float n[7];
  for (size_t i = 0; i < words.size(); ++i) {
    char* end = nullptr;
    n[i] = std::strtof(words[i].c_str(), &end);
    if (end != words[i].c_str() + words[i].size() || !std::isfinite(n[i]))
      return fail("camera: '" + words[i] + "' is not a finite number");
  }
  Viewpoint v = base;
  v.position = {n[0], n[1], n[2]};
  v.target = {n[3], n[4], n[5]};
  if (glm::length(v.target - v.position) < 1e-6f) return fail("camera: the target equals the position");
  if (fov) {
    if (!(n[6] > 0.5f && n[6] < 179.5f)) return fail("camera: fov must be between 0.5 and 179.5 degrees");
    v.yfovRadians = glm::radians(n[6]);
  }
  return v;
}

}  // namespace raylab
