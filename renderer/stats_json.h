// JSON forms of FrameStats and the device, used by --stats, the benchmark and screenshot sidecars; that of
// Settings is renderer/settings/settings_json.h (included here: whoever writes stats writes the settings beside them).
#pragma once

#include <nlohmann/json.hpp>

#include "renderer/frame_stats.h"
#include "renderer/settings/settings_json.h"
#include "renderer/vk/vk_context.h"

namespace raylab {

nlohmann::json toJson(const CommandCounts& c);  // dispatches (direct, indirect), barriers, size writes
// A frame's fixed costs as --stats and the bench write them: toJson(commands) with "submissions".
nlohmann::json commandsJson(const CommandCounts& commands, uint32_t submissions);
nlohmann::json toJson(const FrameStats& s);
// The heatmap shown: {view, bounce, range: [min, max], unit, scale, key_colour, ...}; null without one.
nlohmann::json toJson(const HeatmapStats& h);
nlohmann::json toJson(const DeviceInfo& d);

}  // namespace raylab
