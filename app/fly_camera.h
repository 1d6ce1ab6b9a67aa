// The window's camera: a fly camera (WASD/QE, mouse look) and an orbit mode around a pivot, both producing
// the Viewpoint the renderer takes. Plain math with no window types, so it is tested on the CPU. Also the
// one-line text form of a camera that the UI copies and pastes and scripts use ("camera x y z tx ty tz").
#pragma once

#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "scenes/scene.h"

namespace raylab {

// One frame's worth of input, already mapped from keys and mouse.
struct CameraInput {
  glm::vec3 move{0.0f};  // right, up, forward; each in [-1, 1]
  glm::vec2 look{0.0f};  // mouse movement in pixels while looking (x right, y down)
  float zoom = 0.0f;     // scroll steps (orbit: positive moves closer)
  bool fast = false;     // Shift
  float seconds = 0.0f;  // frame time the movement is scaled by
};

class FlyCamera {
 public:
  // Takes position, direction, up and field of view from `v`; speed is in scene units per second.
  void reset(const Viewpoint& v, float speed);
  Viewpoint viewpoint() const;
  // Returns true when the camera moved.
  bool update(const CameraInput& in);

  // Orbit mode turns around `pivot` and zooms towards it; leaving it keeps the current position.
  void setOrbit(bool on, const glm::vec3& pivot);
  bool orbit() const { return orbit_; }
  const glm::vec3& pivot() const { return pivot_; }
  float speed() const { return speed_; }
  void setSpeed(float s) { speed_ = s; }

  static constexpr float kLookRadiansPerPixel = 0.003f;
  static constexpr float kFastFactor = 5.0f;

 private:
  void turn(float yaw, float pitch);
  bool updateFly(const CameraInput& in);
  bool updateOrbit(const CameraInput& in);

  Viewpoint base_;  // name, up and field of view
  glm::vec3 position_{0.0f};
  glm::vec3 forward_{0.0f, 0.0f, -1.0f};
  glm::vec3 target_{0.0f};  // exactly the viewpoint's until the camera moves (no needless restart)
  float focus_ = 1.0f;  // distance to the target, kept so the target moves with the camera
  float speed_ = 1.0f;
  bool orbit_ = false;
  glm::vec3 pivot_{0.0f};
};

// "camera x y z tx ty tz fov DEG": position, target and vertical field of view in degrees.
std::string cameraToText(const Viewpoint& v);
// The same rounded to three decimals, for reading (the panel's camera line); cameraToText is what is copied.
std::string cameraToShortText(const Viewpoint& v);
// The viewpoint's name, or where it stands when it has none (a moved camera saved in a sidecar).
std::string viewpointLabel(const Viewpoint& v);
// Parses the text form ("camera" prefix and fov optional); fills `base`'s position, target and fov.
// Returns nothing and sets `error` when the text is not a camera.
std::optional<Viewpoint> cameraFromText(const std::string& text, const Viewpoint& base, std::string* error);

}  // namespace raylab
