// JSON forms of Settings, FrameStats and the device, used by --stats, the benchmark and screenshot
// sidecars. settingsFromJson reads back what toJson(Settings) wrote (sidecar round trip).
#pragma once

#include <nlohmann/json.hpp>

#include "renderer/frame_stats.h"
#include "renderer/settings.h"
#include "renderer/vk/vk_context.h"

namespace raylab {

nlohmann::json toJson(const Settings& s);
// Throws SettingsError (a std::invalid_argument) naming the field that is missing or out of range, with the
// ranges and messages every source of Settings is checked with (settings_validation.h).
Settings settingsFromJson(const nlohmann::json& j);
nlohmann::json toJson(const FrameStats& s);
// The heatmap shown: {view, bounce, range: [min, max], unit, scale, key_colour, ...}; null without one.
nlohmann::json toJson(const HeatmapStats& h);
nlohmann::json toJson(const DeviceInfo& d);

}  // namespace raylab
