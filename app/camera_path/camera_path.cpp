#include "app/camera_path/camera_path.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include <nlohmann/json.hpp>

#include "app/command_errors.h"

namespace raylab {
namespace {

using nlohmann::json;

std::string keyframeName(size_t i) { return "keyframe " + std::to_string(i); }

glm::vec3 direction(const CameraKeyframe& k) { return glm::normalize(k.target - k.position); }

// The view may not point along the up vector: the camera's right axis (forward x up) would vanish.
bool alongUp(const glm::vec3& forward, const glm::vec3& up) {
  return !(glm::length(glm::cross(forward, glm::normalize(up))) > 1e-3f);
}

// The index of the keyframe that starts the segment holding keyframe `k`.
size_t segmentStart(const CameraPath& path, size_t k) {
  while (k > 0 && !path.keyframes[k].cut) --k;
  return k;
}

// Centripetal Catmull-Rom (alpha 0.5, Barry-Goldman's pyramid) between p1 and p2, u in [0, 1]; in double, so
// frames near a keyframe do not lose the small steps. Knot intervals are |p_i+1 - p_i|^0.5; a zero interval
// (two keyframes at one place, the camera standing while it turns) takes the middle one's length instead.
glm::dvec3 catmullRom(glm::dvec3 p0, glm::dvec3 p1, glm::dvec3 p2, glm::dvec3 p3, double u) {
  const double d12 = std::sqrt(glm::length(p2 - p1));
  if (d12 < 1e-9) return p1;  // no move between these keyframes: stand still (no bulge from the neighbours)
  double d01 = std::sqrt(glm::length(p1 - p0)), d23 = std::sqrt(glm::length(p3 - p2));
  if (d01 < 1e-9) d01 = d12;
  if (d23 < 1e-9) d23 = d12;
  const double t0 = 0.0, t1 = d01, t2 = t1 + d12, t3 = t2 + d23, t = t1 + u * d12;
  const glm::dvec3 a1 = (t1 - t) / (t1 - t0) * p0 + (t - t0) / (t1 - t0) * p1;
  const glm::dvec3 a2 = (t2 - t) / (t2 - t1) * p1 + (t - t1) / (t2 - t1) * p2;
  const glm::dvec3 a3 = (t3 - t) / (t3 - t2) * p2 + (t - t2) / (t3 - t2) * p3;
  const glm::dvec3 b1 = (t2 - t) / (t2 - t0) * a1 + (t - t0) / (t2 - t0) * a2;
  const glm::dvec3 b2 = (t3 - t) / (t3 - t1) * a2 + (t - t1) / (t3 - t1) * a3;
  return (t2 - t) / (t2 - t1) * b1 + (t - t1) / (t2 - t1) * b2;
}

// The camera between keyframes k and k + 1 of one segment, u in (0, 1).
Viewpoint between(const CameraPath& path, size_t k, double u, const glm::vec3& up) {
  const std::vector<CameraKeyframe>& kf = path.keyframes;
  const size_t first = segmentStart(path, k);
  const bool hasAfter = k + 2 < kf.size() && !kf[k + 2].cut;
  const glm::dvec3 p1 = kf[k].position, p2 = kf[k + 1].position;
  // At a segment's ends the missing neighbour is the mirror image of the other (a natural end tangent).
  const glm::dvec3 p0 = k > first ? glm::dvec3(kf[k - 1].position) : 2.0 * p1 - p2;
  const glm::dvec3 p3 = hasAfter ? glm::dvec3(kf[k + 2].position) : 2.0 * p2 - p1;
  Viewpoint v;
  v.up = up;
  v.position = glm::vec3(catmullRom(p0, p1, p2, p3, u));
  const float t = static_cast<float>(u);
  const float distance = glm::mix(glm::length(kf[k].target - kf[k].position),
                                  glm::length(kf[k + 1].target - kf[k + 1].position), t);
  v.target = v.position + distance * slerpDirection(direction(kf[k]), direction(kf[k + 1]), t, up);
  v.yfovRadians = glm::radians(glm::mix(kf[k].fovDegrees, kf[k + 1].fovDegrees, t));
  return v;
}

Viewpoint exactly(const CameraKeyframe& k, const glm::vec3& up) {
  Viewpoint v;
  v.position = k.position;
  v.target = k.target;
  v.up = up;
  v.yfovRadians = glm::radians(k.fovDegrees);
  return v;
}

// ---- JSON

void rejectUnknownKeys(const json& object, const std::vector<std::string>& known, const std::string& where) {
  for (const auto& item : object.items())
    if (std::find(known.begin(), known.end(), item.key()) == known.end()) {
      const std::string near = nearestName(item.key(), known);
      throw CameraPathError(where + "unknown field '" + item.key() + "'" +
                            (near.empty() ? "" : " (did you mean '" + near + "'?)"));
    }
}

const json& field(const json& object, const char* name, const std::string& where) {
  if (!object.contains(name)) throw CameraPathError(where + "missing '" + name + "'");
  return object.at(name);
}

// A number read as the double JSON holds: beyond float's range it would become inf silently.
float finiteNumber(const json& v, const std::string& what, const std::string& where) {
  if (!v.is_number()) throw CameraPathError(where + "'" + what + "' must be a number, got " + v.dump());
  const double d = v.get<double>();
  if (!std::isfinite(d) || std::fabs(d) > std::numeric_limits<float>::max())
    throw CameraPathError(where + "'" + what + "' must be finite, got " + v.dump());
  return static_cast<float>(d);
}

glm::vec3 vec3Field(const json& object, const char* name, const std::string& where) {
  const json& v = field(object, name, where);
  if (!v.is_array() || v.size() != 3) throw CameraPathError(where + "'" + name + "' must be [x, y, z], got " + v.dump());
  return {finiteNumber(v[0], name, where), finiteNumber(v[1], name, where), finiteNumber(v[2], name, where)};
}

uint32_t frameNumber(const json& v, const std::string& what, const std::string& where) {
  if (!v.is_number_unsigned() || v.get<uint64_t>() > std::numeric_limits<uint32_t>::max())
    throw CameraPathError(where + "'" + what + "' must be a whole number from 0 to 4294967295, got " + v.dump());
  return static_cast<uint32_t>(v.get<uint64_t>());
}

CameraKeyframe keyframeFrom(const json& j, const std::string& where) {
  if (!j.is_object()) throw CameraPathError(where + "must be an object {\"frame\": ..., \"position\": ...}, got " + j.dump());
  rejectUnknownKeys(j, {"frame", "position", "target", "fov", "cut"}, where);
  CameraKeyframe k;
  k.frame = frameNumber(field(j, "frame", where), "frame", where);
  k.position = vec3Field(j, "position", where);
  k.target = vec3Field(j, "target", where);
  k.fovDegrees = finiteNumber(field(j, "fov", where), "fov", where);
  if (j.contains("cut")) {
    if (!j.at("cut").is_boolean()) throw CameraPathError(where + "'cut' must be true or false, got " + j.at("cut").dump());
    k.cut = j.at("cut").get<bool>();
  }
  return k;
}

}  // namespace

glm::vec3 slerpDirection(const glm::vec3& a, const glm::vec3& b, float t, const glm::vec3& up) {
  const float cosine = std::clamp(glm::dot(a, b), -1.0f, 1.0f);
  const float angle = std::acos(cosine);
  if (angle < 1e-6f) return glm::normalize(glm::mix(a, b, t));
  // The unit direction perpendicular to `a` towards `b`; for opposite directions, the turn about `up`
  // (a pan, keeping the horizon), or about any axis when `a` is along `up`.
  glm::vec3 towards = b - a * cosine;
  if (glm::length(towards) < 1e-6f) {
    towards = glm::cross(glm::normalize(up), a);
    if (glm::length(towards) < 1e-6f) towards = glm::cross(glm::vec3(1.0f, 0.0f, 0.0f), a);
    if (glm::length(towards) < 1e-6f) towards = glm::cross(glm::vec3(0.0f, 0.0f, 1.0f), a);
  }
  towards = glm::normalize(towards);
  return glm::normalize(a * std::cos(t * angle) + towards * std::sin(t * angle));
}

void checkCameraPath(const CameraPath& path, const glm::vec3& up) {
  const std::vector<CameraKeyframe>& kf = path.keyframes;
  if (kf.empty()) throw CameraPathError("a path needs at least one keyframe");
  if (path.frames == 0) throw CameraPathError("'frames' must be at least 1");
  for (size_t i = 0; i < kf.size(); ++i) {
    const std::string where = keyframeName(i) + ": ";
    const CameraKeyframe& k = kf[i];
    for (const glm::vec3& v : {k.position, k.target})
      if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
        throw CameraPathError(where + "position and target must be finite");
    if (!std::isfinite(k.fovDegrees) || !(k.fovDegrees > kPathMinFovDegrees && k.fovDegrees < kPathMaxFovDegrees))
      throw CameraPathError(where + "'fov' must be between 0.5 and 179.5 degrees, got " + std::to_string(k.fovDegrees));
    if (!(glm::length(k.target - k.position) >= 1e-6f)) throw CameraPathError(where + "the target equals the position");
    if (alongUp(direction(k), up)) throw CameraPathError(where + "looks straight up or down: the camera has no horizon");
    if (i == 0 && k.cut) throw CameraPathError(where + "cannot be a cut: no keyframe comes before it");
    if (i > 0 && k.frame <= kf[i - 1].frame)
      throw CameraPathError(where + "frame " + std::to_string(k.frame) + " is not after " + keyframeName(i - 1) +
                            "'s frame " + std::to_string(kf[i - 1].frame) + " (frames must increase)");
    // Between two keyframes the look direction turns on the shorter arc; it may pass the pole on the way.
    if (i > 0 && !k.cut)
      for (int s = 1; s < 64; ++s)
        if (alongUp(slerpDirection(direction(kf[i - 1]), direction(k), s / 64.0f, up), up))
          throw CameraPathError(keyframeName(i - 1) + " to " + keyframeName(i) +
                                ": the view turns through straight up or down (add a keyframe between them)");
  }
}

PathCamera cameraAt(const CameraPath& path, uint32_t frame, const glm::vec3& up) {
  const std::vector<CameraKeyframe>& kf = path.keyframes;
  // The last keyframe at or before `frame` (the first one when `frame` comes before it).
  const auto after = std::upper_bound(kf.begin(), kf.end(), frame,
                                      [](uint32_t f, const CameraKeyframe& k) { return f < k.frame; });
  const size_t k = after == kf.begin() ? 0 : size_t(after - kf.begin()) - 1;
  PathCamera c;
  if (frame <= kf[k].frame || k + 1 == kf.size() || kf[k + 1].cut) {
    c.view = exactly(kf[k], up);  // at a keyframe, before the first, or holding a segment's last
    c.cut = kf[k].cut && frame == kf[k].frame;
  } else {
    const double u = double(frame - kf[k].frame) / double(kf[k + 1].frame - kf[k].frame);
    c.view = between(path, k, u, up);
  }
  c.view.name = path.name + " frame " + std::to_string(frame);
  return c;
}

CameraPath parseCameraPath(const std::string& text, const std::string& source, const glm::vec3& up) {
  json j;
  try {
    j = json::parse(text);
  } catch (const json::parse_error& e) {
    throw CameraPathError(source + ": " + e.what());  // nlohmann's message has the line and column
  }
  CameraPath path;
  path.name = source;
  try {
    if (!j.is_object()) throw CameraPathError("must be an object {\"keyframes\": [...]}, got " + j.dump().substr(0, 40));
    rejectUnknownKeys(j, {"frames", "keyframes"}, "");
    const json& keys = field(j, "keyframes", "");
    if (!keys.is_array()) throw CameraPathError("'keyframes' must be an array of keyframes");
    for (size_t i = 0; i < keys.size(); ++i) path.keyframes.push_back(keyframeFrom(keys[i], keyframeName(i) + ": "));
    if (path.keyframes.empty()) throw CameraPathError("'keyframes' is empty: a path needs at least one keyframe");
    path.frames = j.contains("frames") ? frameNumber(j.at("frames"), "frames", "")
                                       : std::max(path.keyframes.back().frame, path.keyframes.back().frame + 1);
    checkCameraPath(path, up);
  } catch (const CameraPathError& e) {
    throw CameraPathError(source + ": " + e.what());
  }
  return path;
}

CameraPath loadCameraPath(const std::string& file, const glm::vec3& up) {
  std::ifstream in(file);
  if (!in) throw CameraPathError("cannot open '" + file + "'");
  std::stringstream text;
  text << in.rdbuf();
  return parseCameraPath(text.str(), file, up);
}

}  // namespace raylab
