// The settings table: every Settings field declared once, as one row (renderer/settings/settings_table.cpp), with its
// command-line flag, JSON key(s) (sidecars, imgui.ini, --stats, the bench's JSONL), CSV column(s), range and
// default, help line, and what a change of it asks of the renderer. Everything that lists settings reads the
// rows instead of a list of its own:
//   - the command line, its help and the flag overlay (app/cli_options.cpp, app/setting_flags.cpp);
//   - the JSON (renderer/settings/settings_json.cpp), and so the sidecars and imgui.ini;
//   - validation and its messages (renderer/settings/settings_validation.cpp);
//   - SettingsChange::between (renderer/settings/settings.cpp);
//   - the bench's sweep axes, labels and CSV settings columns (app/bench/bench_sweep.cpp, app/bench/bench_results.cpp);
//   - the window's ranges (ui/method_panel.cpp).
// tests/cpu/settings/test_settings_table.cpp walks every row. A new setting: its member in Settings, its row here,
// and the code (and shader) that uses it.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "renderer/settings/settings.h"
#include "renderer/settings/settings_validation.h"

namespace raylab {

struct KeyStrategyInfo;  // reorder/key_strategies.h

// What a change of a setting asks of the renderer; SettingsChange::between ORs the effects of the rows that
// differ (and a new cache or path count means new key parameters; any effect, new sort costs).
enum SettingEffect : unsigned {
  kEffectNone = 0,                  // display or measurement only: the frame renders and costs the same
  kEffectReallocate = 1u << 0,      // the path count: new path buffers
  kEffectAccumulation = 1u << 1,    // what a pixel converges to: the image starts again
  kEffectCache = 1u << 2,           // what the length caches learned is void
  kEffectKeyParameters = 1u << 3,   // the uploaded key parameters (grid, thresholds)
  kEffectSortCosts = 1u << 4,       // what the auto sort policy measured
  kEffectScene = 1u << 5,           // what the scene is built from: the window builds it again (and the
                                    // image and caches start again: rows say so with kEffectAccumulation
                                    // and kEffectCache)
};

// One sweep axis of `raylab bench` over a setting: `--<flag> a,b,...` gives one cell per value.
struct SettingAxis {
  const char* flag = nullptr;  // "learn-every-list"; null: the setting is no axis
  const char* help = nullptr;  // its line in `raylab bench --help`, after the flag
  // The strategy fact (reorder/key_strategies.h) that makes the axis apply to a sorted cell (null: every cell).
  bool KeyStrategyInfo::*applies = nullptr;
  // The cell label's part for this setting (" learn=1/4"); empty for none.
  std::string (*label)(const Settings&) = nullptr;
  std::vector<std::string> defaults;  // the values swept when the flag is not given (none: the base's)
  bool labelWhenSwept = false;        // label only cells of a sweep that names the axis (else: every cell)
  bool baselineToo = false;           // the unsorted wavefront is swept too, as a baseline of each value
};

struct SettingRow {
  std::string flag;                   // "learn-every": --learn-every, sweep files, a window script's `set`
  std::string hint;                   // the value in the help ("N", "none|shade"); empty: a switch
  std::string help;                   // the help text ({range} and {default} filled in), "\n" between lines
  std::vector<std::string> members;   // the Settings members the row owns
  std::vector<std::string> jsonKeys;  // its keys in toJson(Settings)
  std::vector<std::string> csvColumns;  // its columns of the bench CSV (none: only in the JSONL)
  double lo = 0, hi = -1;             // numbers: what the flag accepts (lo > hi: not a number)
  unsigned effects = kEffectNone;
  std::string sample;                 // a valid value other than the default, for the tests
  SettingAxis axis;

  std::string jsonError;               // enums: the message for an unknown name (empty: "'key' must be a, b or c")

  // Reads the flag's value into `s`; throws SettingsError with the command line's words.
  void parse(Settings& s, const std::string& text) const { parseFn(*this, s, text); }
  // Reads its keys of `j` into `s` (absent keys: what sidecars from before the setting did); throws
  // SettingsError.
  void read(const nlohmann::json& j, Settings& s) const { readFn(*this, j, s); }
  void check(const Settings& s) const { checkFn(*this, s); }  // throws SettingsError outside the range
  // The flag's value that parse reads back into this setting of `s`.
  std::function<std::string(const Settings& s)> text;
  std::function<bool(const Settings& a, const Settings& b)> same;
  std::function<void(Settings& to, const Settings& from)> copy;
  std::function<void(const Settings& s, nlohmann::json& out)> write;
  std::function<void(const Settings& s, std::map<std::string, std::string>& columns)> csv;
  std::function<void(const SettingRow&, Settings&, const std::string&)> parseFn;
  std::function<void(const SettingRow&, const nlohmann::json&, Settings&)> readFn;
  std::function<void(const SettingRow&, const Settings&)> checkFn;

  bool isSwitch() const { return hint.empty(); }
  NumberRange range() const { return {dashed.c_str(), lo, hi}; }
  std::string dashed;  // "--learn-every", as messages name the flag
};

// Every row, in the order of the help.
const std::vector<SettingRow>& settingRows();
// The row of a flag named without dashes, or null.
const SettingRow* findSettingRow(const std::string& flag);
// The row's range: the window's sliders read their ends here. Throws std::logic_error for an unknown flag.
NumberRange settingRange(const std::string& flag);
// The help lines of every row ("  --bounces N            path length ...\n").
std::string settingsHelp();
// Each row's CSV columns of `s`, by column name.
std::map<std::string, std::string> settingsCsvColumns(const Settings& s);

}  // namespace raylab
