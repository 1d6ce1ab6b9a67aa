#include "renderer/settings/settings_json.h"

#include "renderer/settings/settings_table.h"

#include <string>

namespace raylab {

using nlohmann::json;

json toJson(const Settings& s) {
  json j = json::object();
  for (const SettingRow& row : settingRows()) row.write(s, j);
  return j;
}

// Numbers are range-checked as JSON numbers, before they become uint32_t or float (-5 must not wrap to
// 4294967291, 1e300 must not become inf), with the command line's ranges and messages.
Settings settingsFromJson(const json& j) {
  Settings s;
  try {
    for (const SettingRow& row : settingRows()) row.read(j, s);
  } catch (const json::exception& e) {
    throw SettingsError(std::string("settings: ") + e.what());
  }
  validateSettings(s);  // what no single field shows (paths per frame)
  return s;
}

constexpr const char* kIniKey = "settings=";

std::string settingsIniLine(const Settings& s) { return kIniKey + toJson(s).dump(); }

Settings settingsFromIniLine(const std::string& line) {
  if (line.rfind(kIniKey, 0) != 0) throw SettingsError("imgui.ini: not a settings line");
  json j;
  try {
    j = json::parse(line.substr(std::string(kIniKey).size()));
  } catch (const json::exception& e) {
    throw SettingsError(std::string("settings: ") + e.what());
  }
  return settingsFromJson(j);
}

}  // namespace raylab
