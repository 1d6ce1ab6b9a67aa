#include "app/setting_flags.h"

#include <algorithm>

#include "app/cli_options.h"
#include "renderer/settings/settings_table.h"

namespace raylab {
namespace {

// Flags every mode accepts that are not render settings: skipped by the overlay.
bool isNonSettingFlag(const std::string& name) {
  return name == "device" || name == "validate" || name.rfind("validate=", 0) == 0 || name == "out" || name == "stats";
}

bool parseSwitchValue(const std::string& name, const std::string& value) {
  if (value == "on" || value == "true" || value == "1") return true;
  if (value == "off" || value == "false" || value == "0") return false;
  throw UsageError(name + " expects on or off, got '" + value + "'");
}

// The flag's row parses the value into the fields it owns, with the CLI's own checks and words.
void applyUnchecked(Settings& settings, const std::string& name, const std::string& value) {
  const SettingRow* row = findSettingRow(name);
  if (!row) {
    std::string names;
    for (const std::string& n : settingFlagNames()) names += (names.empty() ? "" : ", ") + n;
    throw UsageError("'" + name + "' is not a render setting; settings: " + names);
  }
  try {
    row->parse(settings, row->isSwitch() ? (parseSwitchValue(name, value) ? "on" : "off") : value);
  } catch (const SettingsError& e) {
    throw UsageError(e.what());
  }
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
    const SettingRow* row = findSettingRow(name);
    bool known = row || isNonSettingFlag(name);
    if (!known && skipUnknown) {
      if (i + 1 < args.size() && args[i + 1].rfind("--", 0) != 0) ++i;
      continue;
    }
    bool takesValue = !(row && row->isSwitch()) && name != "validate" && name.rfind("validate=", 0) != 0;
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
  for (const SettingRow& row : settingRows()) names.push_back(row.flag);
  std::sort(names.begin(), names.end());  // as the messages have always listed them
  return names;
}

}  // namespace raylab
