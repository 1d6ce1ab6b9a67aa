// The JSON sidecar written next to every screenshot (settings, the last frame's statistics, device,
// driver, git revision, camera) and read back by `--settings FILE.json`, so a screenshot can be
// reproduced headless: `raylab render --settings shot.json` renders the same image.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/cli_options.h"
#include "app/learned_history.h"
#include "renderer/frame_stats.h"
#include "renderer/settings/settings.h"
#include "renderer/vk/vk_context.h"
#include "scenes/scene.h"

namespace raylab {

struct SidecarContent {
  std::string kind;   // "render" (the image alone) or "window" (with the panels)
  std::string image;  // file name of the PNG beside it
  uint32_t imageWidth = 0, imageHeight = 0;
  Settings settings;  // frames = the frames accumulated in the image, so a re-render matches it
  Viewpoint camera;
  FrameStats stats;
  DeviceInfo device;
  nlohmann::json panels;  // window shots: where each panel was (ui/panel_layout.h); null: left out
  LearnedState learned;   // whether a re-render's length cache learns what this one did (learned_history.h)
};

// The settings a sidecar records: what was shown. A heatmap the settings cannot show (heatmap_rules.h: the
// window keeps the request and shows the render) is recorded as none, so the sidecar re-renders the image.
Settings settingsShownIn(const Settings& settings);

nlohmann::json makeSidecar(const SidecarContent& content);

struct Sidecar {
  Settings settings;
  std::optional<Viewpoint> camera;  // absent in a plain settings file
  std::string learnedNote;          // "learned_state" of a sidecar whose learned state a re-render cannot match
};
// Reads a sidecar, or a bare toJson(Settings) object. Throws UsageError naming the file and problem.
Sidecar readSidecar(const std::string& path);

// parseCommonOptions with `--settings FILE.json`: the file's settings are the base, the other flags
// change only what they name. `camera` receives the file's camera unless --view overrides it.
// `learnedNote` receives the file's Sidecar::learnedNote.
CommonOptions parseOptionsWithSettingsFile(const std::vector<std::string>& args, std::optional<Viewpoint>* camera,
                                           std::vector<std::string>* rest = nullptr, std::string* learnedNote = nullptr);

}  // namespace raylab
