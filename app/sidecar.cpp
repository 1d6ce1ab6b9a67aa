#include "app/sidecar.h"

#include <algorithm>
#include <fstream>

#include "app/fly_camera.h"
#include "app/setting_flags.h"
#include "renderer/stats_json.h"
#include "renderer/git_revision.h"

namespace raylab {
namespace {

using nlohmann::json;

json toJson(const glm::vec3& v) { return json::array({v.x, v.y, v.z}); }

glm::vec3 vec3From(const json& j) { return {j.at(0).get<float>(), j.at(1).get<float>(), j.at(2).get<float>()}; }

json cameraJson(const Viewpoint& v) {
  return {{"name", v.name},         {"position", toJson(v.position)},
          {"target", toJson(v.target)}, {"up", toJson(v.up)},
          {"yfov_degrees", glm::degrees(v.yfovRadians)}, {"text", cameraToText(v)}};
}

Viewpoint cameraFrom(const json& j) {
  Viewpoint v;
  v.name = j.value("name", std::string());
  v.position = vec3From(j.at("position"));
  v.target = vec3From(j.at("target"));
  v.up = vec3From(j.at("up"));
  v.yfovRadians = glm::radians(j.at("yfov_degrees").get<float>());
  return v;
}

}  // namespace

nlohmann::json makeSidecar(const SidecarContent& c) {
  json sidecar = {{"kind", c.kind},
                  {"image", c.image},
                  {"image_width", c.imageWidth},
                  {"image_height", c.imageHeight},
                  {"git_revision", gitRevision()},
                  {"device", toJson(c.device)},
                  {"settings", toJson(c.settings)},
                  {"camera", cameraJson(c.camera)},
                  {"heatmap", toJson(c.stats.heatmap)},  // the legend of a heatmap image: range, unit, scale
                  {"stats", toJson(c.stats)}};
  if (!c.panels.is_null()) sidecar["panels"] = c.panels;
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
  } catch (const json::exception& e) {
    throw UsageError("--settings " + path + ": " + e.what());
  } catch (const std::invalid_argument& e) {
    throw UsageError("--settings " + path + ": " + e.what());
  }
  return out;
}

CommonOptions parseOptionsWithSettingsFile(const std::vector<std::string>& args, std::optional<Viewpoint>* camera,
                                           std::vector<std::string>* rest) {
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
  options.settings = overlaySettingFlags(sidecar.settings, others, /*skipUnknown=*/rest != nullptr);
  bool viewGiven = std::find(others.begin(), others.end(), "--view") != others.end();
  if (camera && sidecar.camera && !viewGiven) *camera = sidecar.camera;
  return options;
}

}  // namespace raylab
