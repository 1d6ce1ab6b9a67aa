#include "app/sidecar.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <stdexcept>

#include "app/fly_camera.h"
#include "app/setting_flags.h"
#include "renderer/heatmap/heatmap_rules.h"
#include "renderer/stats_json.h"
#include "renderer/git_revision.h"

namespace raylab {
namespace {

using nlohmann::json;

json toJson(const glm::vec3& v) { return json::array({v.x, v.y, v.z}); }

// A camera number read as the double JSON holds: beyond float's range it would silently become inf
// (found by tests/fuzz: a sidecar with "position": [1e300, 0, 0] rendered from infinity).
float finiteFloat(const json& v, const std::string& what) {
  double d = v.get<double>();
  if (!std::isfinite(d) || std::fabs(d) > std::numeric_limits<float>::max())
    throw std::invalid_argument("camera: '" + what + "' must be finite numbers, got " + v.dump());
  return static_cast<float>(d);
}

glm::vec3 vec3From(const json& j, const std::string& what) {
  if (!j.is_array() || j.size() != 3) throw std::invalid_argument("camera: '" + what + "' must be [x, y, z], got " + j.dump());
  return {finiteFloat(j.at(0), what), finiteFloat(j.at(1), what), finiteFloat(j.at(2), what)};
}

json cameraJson(const Viewpoint& v) {
  return {{"name", v.name},         {"position", toJson(v.position)},
          {"target", toJson(v.target)}, {"up", toJson(v.up)},
          {"yfov_degrees", glm::degrees(v.yfovRadians)}, {"text", cameraToText(v)}};
}

Viewpoint cameraFrom(const json& j) {
  Viewpoint v;
  v.name = j.value("name", std::string());
  v.position = vec3From(j.at("position"), "position");
  v.target = vec3From(j.at("target"), "target");
  v.up = vec3From(j.at("up"), "up");
  // The checks and limits of the camera's text form (cameraFromText), plus an up that is not the view axis.
  float fov = finiteFloat(j.at("yfov_degrees"), "yfov_degrees");
  if (!(fov > 0.5f && fov < 179.5f)) throw std::invalid_argument("camera: fov must be between 0.5 and 179.5 degrees");
  v.yfovRadians = glm::radians(fov);
  glm::vec3 forward = v.target - v.position;
  if (!(glm::length(forward) >= 1e-6f)) throw std::invalid_argument("camera: the target equals the position");
  if (!(glm::length(glm::cross(forward, v.up)) > 1e-6f * glm::length(forward) * glm::length(v.up)))
    throw std::invalid_argument("camera: 'up' is zero or along the view direction");
  return v;
}

}  // namespace

Settings settingsShownIn(const Settings& settings) {
  Settings shown = settings;
  shown.heatmap = heatmapShown(settings);
  return shown;
}

nlohmann::json makeSidecar(const SidecarContent& c) {
  json sidecar = {{"kind", c.kind},
                  {"image", c.image},
                  {"image_width", c.imageWidth},
                  {"image_height", c.imageHeight},
                  {"git_revision", gitRevision()},
                  {"device", toJson(c.device)},
                  {"settings", toJson(settingsShownIn(c.settings))},
                  {"camera", cameraJson(c.camera)},
                  {"heatmap", toJson(c.stats.heatmap)},  // the legend of a heatmap image: range, unit, scale
                  {"stats", toJson(c.stats)}};
  if (!c.panels.is_null()) sidecar["panels"] = c.panels;
  // What was asked for and not shown, for the reader: a re-render reads only "settings".
  if (std::optional<std::string> why = heatmapUnavailable(c.settings))
    sidecar["heatmap_not_shown"] = {{"asked", toString(c.settings.heatmap)}, {"why", *why}};
  if (!c.learned.note.empty())
    sidecar["learned_state"] = {{"reproducible", c.learned.reproducible}, {"note", c.learned.note}};
  return sidecar;
}

Sidecar readSidecar(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw UsageError("--settings: cannot open '" + path + "'");
  Sidecar out;
  try {
    json j = json::parse(in);
    const json& settings = j.contains("settings") ? j.at("settings") : j;
    out.settings = settingsFromJson(settings);
    if (j.contains("camera")) out.camera = cameraFrom(j.at("camera"));
    if (j.contains("learned_state") && !j.at("learned_state").value("reproducible", true))
      out.learnedNote = j.at("learned_state").value("note", std::string("the learned state differs"));
  } catch (const json::exception& e) {
    throw UsageError("--settings " + path + ": " + e.what());
  } catch (const std::invalid_argument& e) {
    throw UsageError("--settings " + path + ": " + e.what());
  }
  return out;
}

CommonOptions parseOptionsWithSettingsFile(const std::vector<std::string>& args, std::optional<Viewpoint>* camera,
                                           std::vector<std::string>* rest, std::string* learnedNote) {
  std::vector<std::string> others;
  std::string file;
  for (size_t i = 0; i < args.size(); ++i) {
    if (args[i] != "--settings") {
      others.push_back(args[i]);
      continue;
    }
    if (i + 1 >= args.size()) throw UsageError("--settings needs a value");
    file = args[++i];
  }
  std::vector<std::string> unknown;
  CommonOptions options = parseCommonOptions(others, rest ? &unknown : nullptr);
  if (rest) *rest = unknown;
  if (file.empty()) return options;

  Sidecar sidecar = readSidecar(file);
  if (learnedNote) *learnedNote = sidecar.learnedNote;
  options.settings = overlaySettingFlags(sidecar.settings, others, /*skipUnknown=*/rest != nullptr);
  bool viewGiven = std::find(others.begin(), others.end(), "--view") != others.end();
  if (camera && sidecar.camera && !viewGiven) *camera = sidecar.camera;
  return options;
}

}  // namespace raylab
