#include "app/setting_flags.h"

#include <functional>
#include <map>

#include "app/cli_options.h"
#include "renderer/settings_validation.h"

namespace raylab {
namespace {

using Copy = std::function<void(Settings& to, const Settings& from)>;

// Which Settings fields each flag writes. A flag missing here cannot be overlaid: the test
// SettingFlags.EveryRenderFlagIsOverlaid compares this table with commonOptionsHelp().
const std::map<std::string, Copy>& fieldsOfFlag() {
  static const std::map<std::string, Copy> table = {
      {"scene", [](Settings& t, const Settings& f) { t.scene = f.scene; }},
      {"view", [](Settings& t, const Settings& f) { t.view = f.view; }},
      {"size", [](Settings& t, const Settings& f) { t.width = f.width, t.height = f.height; }},
      {"bounces", [](Settings& t, const Settings& f) { t.bounces = f.bounces; }},
      {"spp", [](Settings& t, const Settings& f) { t.sppPerFrame = f.sppPerFrame; }},
      {"frames", [](Settings& t, const Settings& f) { t.frames = f.frames; }},
      {"seed", [](Settings& t, const Settings& f) { t.seed = f.seed; }},
      {"exposure", [](Settings& t, const Settings& f) { t.exposure = f.exposure; }},
      {"kernel", [](Settings& t, const Settings& f) { t.kernel = f.kernel; }},
      {"tracer", [](Settings& t, const Settings& f) { t.tracer = f.tracer; }},
      {"bvh", [](Settings& t, const Settings& f) { t.bvh = f.bvh; }},
      {"ser", [](Settings& t, const Settings& f) { t.ser = f.ser; }},
      {"strategy", [](Settings& t, const Settings& f) { t.strategy = f.strategy; }},
      {"sort", [](Settings& t, const Settings& f) { t.sort = f.sort; }},
      {"sort-policy", [](Settings& t, const Settings& f) { t.sortPolicy = f.sortPolicy; }},
      {"sort-bits", [](Settings& t, const Settings& f) { t.sortBits = f.sortBits; }},
      {"fusion", [](Settings& t, const Settings& f) { t.fusion = f.fusion; }},
      {"compaction", [](Settings& t, const Settings& f) { t.compaction = f.compaction; }},
      {"trace-shade", [](Settings& t, const Settings& f) { t.traceShade = f.traceShade; }},
      {"grid", [](Settings& t, const Settings& f) { t.grid = f.grid; }},
      {"clamp", [](Settings& t, const Settings& f) { t.clampToCamera = f.clampToCamera, t.clampDistance = f.clampDistance; }},
      {"fixed-factor", [](Settings& t, const Settings& f) { t.fixedFactor = f.fixedFactor; }},
      {"ema-alpha", [](Settings& t, const Settings& f) { t.emaAlpha = f.emaAlpha; }},
      {"gauss-outlier", [](Settings& t, const Settings& f) { t.gaussOutlier = f.gaussOutlier; }},
      {"gauss-reset", [](Settings& t, const Settings& f) { t.gaussReset = f.gaussReset; }},
      {"learn-every", [](Settings& t, const Settings& f) { t.learnEvery = f.learnEvery; }},
      {"count-simt", [](Settings& t, const Settings& f) { t.countSimt = f.countSimt; }},
      {"heatmap", [](Settings& t, const Settings& f) { t.heatmap = f.heatmap; }},
      {"heatmap-bounce", [](Settings& t, const Settings& f) { t.heatmapBounce = f.heatmapBounce; }},
      {"heatmap-key-colour", [](Settings& t, const Settings& f) { t.heatmapKeyColour = f.heatmapKeyColour; }},
      {"heatmap-scale", [](Settings& t, const Settings& f) { t.heatmapScale = f.heatmapScale; }},
      {"heatmap-range", [](Settings& t, const Settings& f) { t.heatmapRange = f.heatmapRange; }},
  };
  return table;
}

bool isSwitch(const std::string& name) { return name == "count-simt"; }

// Flags every mode accepts that are not render settings: skipped by the overlay.
bool isNonSettingFlag(const std::string& name) {
  return name == "device" || name == "validate" || name.rfind("validate=", 0) == 0 || name == "out" || name == "stats";
}

// Parses one flag with the CLI's own parser, so a script's `set` is validated exactly as the flag is.
Settings parseFlags(const std::vector<std::string>& args) { return parseCommonOptions(args).settings; }

bool parseSwitchValue(const std::string& name, const std::string& value) {
  if (value == "on" || value == "true" || value == "1") return true;
  if (value == "off" || value == "false" || value == "0") return false;
  throw UsageError(name + " expects on or off, got '" + value + "'");
}

}  // namespace

namespace {

void applyUnchecked(Settings& settings, const std::string& name, const std::string& value) {
  auto it = fieldsOfFlag().find(name);
  if (it == fieldsOfFlag().end()) {
    std::string names;
    for (const std::string& n : settingFlagNames()) names += (names.empty() ? "" : ", ") + n;
    throw UsageError("'" + name + "' is not a render setting; settings: " + names);
  }
  if (name == "clamp" && value == "off") {
    settings.clampToCamera = false;
    return;
  }
  if (isSwitch(name)) {
    Settings parsed = parseFlags(parseSwitchValue(name, value) ? std::vector<std::string>{"--" + name}
                                                                   : std::vector<std::string>{});
    it->second(settings, parsed);
    return;
  }
  it->second(settings, parseFlags({"--" + name, value}));
}

}  // namespace

// The flag alone was checked by the CLI's parser; the settings it lands in are checked as a whole (e.g.
// --size and --spp together), and are left unchanged when they fail.
void applySettingFlag(Settings& settings, const std::string& name, const std::string& value) {
  Settings next = settings;
  applyUnchecked(next, name, value);
  if (std::optional<std::string> error = settingsError(next)) throw UsageError(*error);
  settings = next;
}

Settings overlaySettingFlags(const Settings& base, const std::vector<std::string>& args, bool skipUnknown) {
  Settings out = base;
  for (size_t i = 0; i < args.size(); ++i) {
    if (args[i].rfind("--", 0) != 0) throw UsageError("unexpected argument '" + args[i] + "'");
    std::string name = args[i].substr(2);
    bool known = fieldsOfFlag().count(name) || isNonSettingFlag(name);
    if (!known && skipUnknown) {
      if (i + 1 < args.size() && args[i + 1].rfind("--", 0) != 0) ++i;
      continue;
    }
    bool takesValue = !isSwitch(name) && name != "validate" && name.rfind("validate=", 0) != 0;
    if (takesValue && i + 1 >= args.size()) throw UsageError(args[i] + " needs a value");
    std::string value = takesValue ? args[++i] : "on";
    if (isNonSettingFlag(name)) continue;
    applyUnchecked(out, name, value);
  }
  // Checked once all flags are in: their order must not matter (--size before or after --spp).
  if (std::optional<std::string> error = settingsError(out)) throw UsageError(*error);
  return out;
}

std::vector<std::string> settingFlagNames() {
  std::vector<std::string> names;
  for (const auto& [name, copy] : fieldsOfFlag()) names.push_back(name);
  return names;
}

}  // namespace raylab
