#include "app/window_command.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "app/command_errors.h"
#include "app/config_dir.h"
#include "app/render_command.h"
#include "app/scene_setup.h"
#include "app/sidecar.h"
#include "app/ui_script.h"
#include "app/window/window_options.h"
#include "renderer/checked_write.h"

#ifdef RAYLAB_WITH_WINDOW
#include "app/window/glfw_window.h"
#endif

namespace raylab {
namespace {

const char* const kWindowHelp =
    "window options:\n"
    "  --window-size WxH      window size (default 1280x720, or as last closed); the window renders at its\n"
    "                         size times --scale (--size, the resolution, only where raylab renders headless\n"
    "                         for want of a display)\n"
    "  --scale S              render resolution / window resolution, 0.05..2 (default 1; 0.25 on CPU devices)\n"
    "  --script FILE          run UI actions from FILE, one a line, then quit:\n"
    "                           set KEY VALUE (any render flag without dashes: set heatmap sort-key),\n"
    "                           camera X Y Z TX TY TZ [fov D], view NAME, wait N (frames),\n"
    "                           screenshot NAME, screenshot-window NAME, reset-layout,\n"
    "                           restart-learning, memory LABEL, press KEY (a hotkey: press K records a\n"
    "                           camera path), quit; # starts a comment\n"
    "  --screenshot-dir DIR   where F12 / Shift+F12 and scripts save (default CONFIG/screenshots)\n"
    "  --ini FILE             layout and last settings (default CONFIG/imgui.ini; none for scripts)\n"
    "  CONFIG is $XDG_CONFIG_HOME/raylab or ~/.config/raylab\n"
    "  --reset                start with the default layout and settings\n"
    "  --frame-log FILE       write one JSON line per UI frame: ui_ms, render_ms, frame_done, preview, ...\n"
    "                         (python3 app/frame_log_report.py FILE reports p50/p95 and time to preview)\n"
    "  --render-budget-ms MS  render work per UI frame, 1..1000 (default 40): a frame that takes longer\n"
    "                         renders its stages over several UI frames, after a coarse preview\n"
    "  --camera-path FILE|builtin:NAME  play a camera path: one path frame per rendered frame, as `raylab render\n"
    "                         --camera-path` replays it (Play/Stop in the Scene panel, or P); K records one\n";

// The window's own flags that take a value; everything else is a render flag.
bool isWindowValueFlag(const std::string& a) {
  for (const char* flag :
       {"--script", "--screenshot-dir", "--ini", "--scale", "--frame-log", "--render-budget-ms", "--window-size"})
    if (a == flag) return true;
  return false;
}

// The frame log is opened here once, so a file that cannot be written is a usage error before any window.
std::string checkedFrameLog(const std::string& path) {
  try {
    AppendFile(path, AppendFile::Start::Empty).close();
  } catch (const WriteError& e) {
    throw UsageError(std::string("--frame-log: ") + e.what());
  }
  return path;
}

// --window-size WxH: within what a window system could give (the render's own limit, 8192, per side).
void parseWindowSize(const std::string& text, WindowOptions& o) {
  const size_t x = text.find('x');
  if (x == std::string::npos) throw UsageError("--window-size expects WxH (e.g. 1280x720), got '" + text + "'");
  o.width = int(parseUint("--window-size width", text.substr(0, x), 1, SettingLimits::kMaxSize));
  o.height = int(parseUint("--window-size height", text.substr(x + 1), 1, SettingLimits::kMaxSize));
}

void printWindowUsage(const std::string& error) {
  printUsageError("raylab", error);
}

std::string valueOf(const std::vector<std::string>& rest, size_t& i) {
  if (i + 1 >= rest.size() || rest[i + 1].rfind("--", 0) == 0) throw UsageError(rest[i] + " needs a value");
  return rest[++i];
}

// Splits the window's own flags from the render flags (which parseOptionsWithSettingsFile checks).
WindowOptions parseWindowOptions(const std::vector<std::string>& args) {
  WindowOptions o;
  const std::string config = configDir();
  o.screenshotDir = config.empty() ? "screenshots" : config + "/screenshots";
  o.iniPath = config.empty() ? "" : config + "/imgui.ini";  // no config folder: remember nothing
  std::optional<Viewpoint> camera;
  std::vector<std::string> rest;
  o.common = parseOptionsWithSettingsFile(args, &camera, &rest);
  bool iniGiven = false;
  for (size_t i = 0; i < rest.size(); ++i) {
    const std::string& a = rest[i];
    if (a == "--script") o.script = valueOf(rest, i);
    else if (a == "--screenshot-dir") o.screenshotDir = valueOf(rest, i);
    else if (a == "--ini") o.iniPath = valueOf(rest, i), iniGiven = true;
    else if (a == "--reset") o.reset = true;
    else if (a == "--window-size") parseWindowSize(valueOf(rest, i), o);
    else if (a == "--scale") o.scale = parseFloat("--scale", valueOf(rest, i), 0.05f, 2.0f);
    else if (a == "--frame-log") o.frameLog = checkedFrameLog(valueOf(rest, i));
    else if (a == "--render-budget-ms") o.renderBudgetMs = parseFloat("--render-budget-ms", valueOf(rest, i), 1.0f, 1000.0f);
    else if (a == "--camera-path") o.cameraPath = valueOf(rest, i);  // resolved against the scene as it loads
    else {
      std::vector<std::string> known = commonOptionNames();
      for (const char* f : {"--script", "--screenshot-dir", "--ini", "--reset", "--window-size", "--scale", "--frame-log",
                            "--render-budget-ms", "--camera-path"})
        known.push_back(f);
      throw UsageError(unknownOptionMessage(a, known));
    }
  }
  for (size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--settings" && i + 1 < args.size()) {
      o.sidecar = readSidecar(args[++i]);
      o.sidecar->camera = camera;  // cleared by parseOptionsWithSettingsFile when --view overrides it
      continue;
    }
    if (isWindowValueFlag(args[i])) ++i;
    else if (args[i] != "--reset") o.renderArgs.push_back(args[i]);
  }
  if (!o.script.empty() && !iniGiven) o.iniPath.clear();  // scripted runs neither read nor write imgui.ini
  if (!o.script.empty()) loadScript(o.script);            // a broken script stops here, before any window
  return o;
}

// The render command's arguments: everything but the window's own flags.
std::vector<std::string> renderArgsOf(const std::vector<std::string>& args) {
  std::vector<std::string> out;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (isWindowValueFlag(a)) ++i;
    else if (a != "--reset") out.push_back(a);
  }
  return out;
}

// Without a window, `raylab` still shows the scene: unless frames or a budget are given, it accumulates
// for kHeadlessBudget seconds (one sample per pixel would be noise; 10 s on two CPU cores is a clear image
// of the default overview).
constexpr const char* kHeadlessBudget = "10";

int renderHeadless(const std::string& why, const std::vector<std::string>& args) {
  std::fprintf(stderr, "raylab: %s; rendering headless instead (raylab render --help for the options)\n", why.c_str());
  std::vector<std::string> renderArgs = renderArgsOf(args);
  auto given = [&](const char* flag) { return std::find(args.begin(), args.end(), flag) != args.end(); };
  // A camera path renders its own frames, one image each: no accumulation budget applies to it.
  if (!given("--frames") && !given("--time-budget") && !given("--settings") && !given("--camera-path"))
    renderArgs.insert(renderArgs.end(), {"--time-budget", kHeadlessBudget});
  return runRenderCommand(renderArgs);
}

bool haveDisplayVariable() {
  const char* x = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  return (x && *x) || (wayland && *wayland);
}

}  // namespace

std::string windowOptionsHelp() { return kWindowHelp; }

int runWindowCommand(const std::vector<std::string>& args) {
  WindowOptions options;
  const int parsed = withCommandErrors(printWindowUsage, [&] {
    options = parseWindowOptions(args);
    return int(kExitOk);
  });
  if (parsed != kExitOk) return parsed;
#ifdef RAYLAB_WITH_WINDOW
  const bool scripted = !options.script.empty();
  if (!haveDisplayVariable()) {
    if (scripted) {
      std::fprintf(stderr, "raylab: --script needs a display (DISPLAY or WAYLAND_DISPLAY; try xvfb-run)\n");
      return kExitFailure;
    }
    return renderHeadless("no display (neither DISPLAY nor WAYLAND_DISPLAY is set)", args);
  }
  return withCommandErrors(printWindowUsage, [&] {
    try {
      return runLabWindow(options);
    } catch (const NoDisplayError& e) {
      if (scripted) {
        std::fprintf(stderr, "raylab: %s\n", e.what());
        return int(kExitFailure);
      }
      return renderHeadless(e.what(), args);
    }
  });
#else
  (void)haveDisplayVariable;
  if (!options.script.empty()) {
    std::fprintf(stderr, "raylab: this build has no window (RAYLAB_HEADLESS_ONLY); --script needs one\n");
    return kExitFailure;
  }
  return renderHeadless("this build has no window (RAYLAB_HEADLESS_ONLY)", args);
#endif
}

}  // namespace raylab
