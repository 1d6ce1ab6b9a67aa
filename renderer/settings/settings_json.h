// The JSON form of Settings (screenshot sidecars, imgui.ini, --stats, the bench's JSONL): one key or more per
// row of the settings table (renderer/settings/settings_table.h). settingsFromJson reads back what toJson wrote.
#pragma once

#include <nlohmann/json.hpp>

#include "renderer/settings/settings.h"

namespace raylab {

nlohmann::json toJson(const Settings& s);
// Throws SettingsError (a std::invalid_argument) naming the field that is missing or out of range, with the
// ranges and messages every source of Settings is checked with (settings_validation.h). Keys older sidecars
// lack take what those versions did.
Settings settingsFromJson(const nlohmann::json& j);

// The line of imgui.ini that keeps the last Settings ("settings=" and the JSON; ui/settings_ini.cpp), and
// back: throws SettingsError for a line that is not one or holds bad settings.
std::string settingsIniLine(const Settings& s);
Settings settingsFromIniLine(const std::string& line);

}  // namespace raylab
