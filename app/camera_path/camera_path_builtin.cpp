#include "app/camera_path/camera_path_builtin.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "app/command_errors.h"
#include "scenes/clutter.h"
#include "scenes/temple_detail.h"

namespace raylab {
namespace {

constexpr float kPi = 3.14159265358979f;

bool isTemple(const Scene& scene) {
  const std::string detail = kTempleDetailName;
  return scene.name == "temple" || scene.name.compare(0, detail.size(), detail) == 0;
}

const Viewpoint& viewpoint(const Scene& scene, const char* name) {
  const Viewpoint* v = scene.findViewpoint(name);
  if (!v) throw std::logic_error(scene.name + " has no viewpoint '" + name + "' for its built-in paths");
  return *v;
}

CameraKeyframe keyframe(uint32_t frame, glm::vec3 position, glm::vec3 target, float fovDegrees, bool cut = false) {
  return {frame, position, target, fovDegrees, cut};
}

CameraKeyframe keyframe(uint32_t frame, const Viewpoint& v, bool cut = false) {
  return keyframe(frame, v.position, v.target, glm::degrees(v.yfovRadians), cut);
}

// One turn around `centre` on an ellipse of radii `radius` (x, z) at height `height`, looking at `centre`:
// a keyframe every eighth of the turn, the last where the first is (the spline closes the loop smoothly in
// between; only at the ends is the tangent the mirrored one).
CameraPath orbitAround(glm::vec3 centre, glm::vec2 radius, float height, float fovDegrees) {
  CameraPath path;
  path.frames = kBuiltinPathFrames;
  constexpr int kSteps = 8;
  for (int i = 0; i <= kSteps; ++i) {
    const float a = 2.0f * kPi * float(i) / kSteps;
    const glm::vec3 p(centre.x + radius.x * std::cos(a), height, centre.z + radius.y * std::sin(a));
    path.keyframes.push_back(keyframe(uint32_t(i) * (kBuiltinPathFrames - 1) / kSteps, p, centre, fovDegrees));
  }
  return path;
}

// Any scene, glTF included: a slow turn just outside the bounds, above them, looking at the lower middle.
// Outside, because a scene of unknown layout may have anything inside its bounds (an object fills them).
CameraPath boundsOrbit(const Scene& scene) {
  const Bounds b = scene.bounds();
  const glm::vec3 e = b.extent(), c = b.center();
  const float across = std::max(std::max(e.x, e.z), 1e-3f);
  return orbitAround({c.x, b.min.y + 0.25f * e.y, c.z}, glm::vec2(0.6f * across), b.max.y + 0.25f * e.y, 50.0f);
}

// Shots of `kBuiltinShotFrames` frames, the views in turn, each shot a slow push in (a tenth of the way to
// the view's target); every shot after the first starts with a cut.
CameraPath alternatingShots(const Viewpoint& a, const Viewpoint& b) {
  CameraPath path;
  path.frames = kBuiltinPathFrames;
  for (uint32_t shot = 0; shot * kBuiltinShotFrames < kBuiltinPathFrames; ++shot) {
    const Viewpoint& v = shot % 2 == 0 ? a : b;
    const uint32_t start = shot * kBuiltinShotFrames;
    path.keyframes.push_back(keyframe(start, v, shot > 0));
    path.keyframes.push_back(keyframe(start + kBuiltinShotFrames - 1, v.position + 0.1f * (v.target - v.position),
                                      v.target, glm::degrees(v.yfovRadians)));
  }
  return path;
}

// From the alley viewpoint up the alley, west through the passage into the courtyard (scenes/temple.cpp,
// addAlley: the opening at z 20 to 24, below y 6, in the wall at x 44 to 50), across it and through the
// hall's north door (addHall: x -3 to 3, below y 7, in the wall at z -26 to -24) to the hall viewpoint.
// tests/cpu/camera_path/test_camera_path_builtin.cpp checks that no step between frames passes through a triangle.
CameraPath templeWalk(const Scene& scene) {
  const Viewpoint& alley = viewpoint(scene, "alley");
  const Viewpoint& hall = viewpoint(scene, "hall");
  const float fov = glm::degrees(alley.yfovRadians);
  CameraPath path;
  path.frames = kBuiltinPathFrames;
  path.keyframes = {
      keyframe(0, alley),
      keyframe(90, {53, 2.5f, 16}, {53, 2.5f, 40}, fov),
      keyframe(120, {53, 2.5f, 22}, {40, 2.5f, 22}, fov),   // turn west at the passage
      keyframe(140, {47, 2.5f, 22}, {30, 2.5f, 22}, fov),   // in it
      keyframe(155, {41, 2.5f, 22}, {25, 2.5f, 10}, fov),   // out in the courtyard
      keyframe(190, {14, 3.0f, -2}, {0, 3.5f, -20}, fov),
      keyframe(210, {0, 3.5f, -14}, {0, 3.5f, -30}, fov),  // in line with the hall's door
      keyframe(225, {0, 3.5f, -21}, {0, 4.0f, -40}, fov),
      keyframe(kBuiltinPathFrames - 1, hall),
  };
  return path;
}

// The clutter room's orbit: inside it (its walls close it), half way to the walls, at eye height.
CameraPath clutterOrbit() {
  const Bounds room = clutterRoomInterior();
  const glm::vec3 e = room.extent(), c = room.center();
  return orbitAround({c.x, room.min.y + 0.25f * e.y, c.z}, {0.25f * e.x, 0.25f * e.z}, room.min.y + 0.55f * e.y, 65.0f);
}

// Sideways along the south wall's shelves from the shelves viewpoint, the view turning a little with it.
CameraPath clutterPan(const Scene& scene) {
  const Viewpoint& shelves = viewpoint(scene, "shelves");
  const float reach = 0.3f * clutterRoomInterior().extent().x;
  CameraPath path;
  path.frames = kBuiltinPathFrames;
  constexpr int kSteps = 3;  // collinear, evenly spaced keyframes: the spline moves at constant speed
  for (int i = 0; i <= kSteps; ++i) {
    const float x = reach * (2.0f * float(i) / kSteps - 1.0f);
    path.keyframes.push_back(keyframe(uint32_t(i) * (kBuiltinPathFrames - 1) / kSteps, shelves.position + glm::vec3(x, 0, 0),
                                      shelves.target + glm::vec3(0.6f * x, 0, 0), glm::degrees(shelves.yfovRadians)));
  }
  return path;
}

std::string nameList(const std::vector<std::string>& names) {
  std::string s;
  for (const std::string& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

}  // namespace

glm::vec3 sceneUp(const Scene& scene) { return scene.viewpoints.empty() ? Viewpoint{}.up : scene.viewpoints.front().up; }

std::vector<std::string> builtinCameraPathNames(const Scene& scene) {
  if (isTemple(scene)) return {"orbit", "walk", "cut"};
  if (isClutterName(scene.name)) return {"orbit", "pan", "cut"};
  return {"orbit"};
}

CameraPath builtinCameraPath(const Scene& scene, const std::string& name) {
  const std::vector<std::string> names = builtinCameraPathNames(scene);
  if (std::find(names.begin(), names.end(), name) == names.end()) {
    const std::string near = name == "list" ? "" : nearestName(name, names);
    throw CameraPathError((name == "list" ? "" : "no built-in path '" + name + "'" +
                                                     (near.empty() ? "" : " (did you mean builtin:" + near + "?)") + "; ") +
                          "the built-in paths of " + scene.name + " are: " + nameList(names) + " (as builtin:NAME)");
  }
  CameraPath path;
  if (isTemple(scene)) {
    path = name == "walk"  ? templeWalk(scene)
           : name == "cut" ? alternatingShots(viewpoint(scene, "hall"), viewpoint(scene, "openings"))
                           : boundsOrbit(scene);
  } else if (isClutterName(scene.name)) {
    path = name == "pan"   ? clutterPan(scene)
           : name == "cut" ? alternatingShots(viewpoint(scene, "shelves"), viewpoint(scene, "floor"))
                           : clutterOrbit();
  } else {
    path = boundsOrbit(scene);
  }
  path.name = kBuiltinPathPrefix + name;
  checkCameraPath(path, sceneUp(scene));  // a built-in path is input like a file's: the same rules
  return path;
}

CameraPath resolveCameraPath(const std::string& spec, const Scene& scene) {
  const std::string prefix = kBuiltinPathPrefix;
  if (spec.compare(0, prefix.size(), prefix) == 0) return builtinCameraPath(scene, spec.substr(prefix.size()));
  return loadCameraPath(spec, sceneUp(scene));
}

}  // namespace raylab
