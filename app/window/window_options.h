// What `raylab` (the window mode) was asked for on the command line, parsed by app/window_command.cpp.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "app/cli_options.h"
#include "app/sidecar.h"

namespace raylab {

struct WindowOptions {
  CommonOptions common;                // device, validation; render flags already checked
  std::vector<std::string> renderArgs; // the render flags as given, laid over the remembered settings
  std::optional<Sidecar> sidecar;      // --settings FILE.json: settings (and camera) to start from
  std::string script;                  // --script FILE
  std::string screenshotDir;            // --screenshot-dir DIR; default configDir()/screenshots
  std::string iniPath;                 // --ini FILE; default configDir()/imgui.ini; scripts none unless given
  bool reset = false;                  // --reset: ignore imgui.ini (it is rewritten on exit)
  int width = 0, height = 0;           // --window-size: the window's size; 0: remembered or default
  std::optional<float> scale;          // --scale: render size / window size
  std::string frameLog;                // --frame-log FILE: one JSON line per UI frame (frame_log.h)
  double renderBudgetMs = 40.0;        // --render-budget-ms: render work per UI frame (live_render.h)
  std::string cameraPath;              // --camera-path FILE|builtin:NAME: played from the start (path_player.h)
};

// Opens the window and runs until it is closed or the script quits. Returns an exit code; throws
// NoDisplayError when there is no display to open a window on.
int runLabWindow(const WindowOptions& options);

}  // namespace raylab
