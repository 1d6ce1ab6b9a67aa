#include "app/cli_options.h"

#include <algorithm>

#include "app/command_errors.h"

#include "renderer/settings/settings_table.h"
#include "renderer/settings/settings_validation.h"

namespace raylab {

// Range checks and their wording are settings_validation's, shared with sidecars, scripts and imgui.ini.
std::optional<std::string> takeFlag(std::vector<std::string>& args, const std::string& flag) {
  std::optional<std::string> value;
  for (size_t i = 0; i < args.size(); ++i) {
    if (args[i] != flag) continue;
    if (i + 1 >= args.size()) throw UsageError(flag + " needs a value");
    value = args[i + 1];
    args.erase(args.begin() + static_cast<std::ptrdiff_t>(i), args.begin() + static_cast<std::ptrdiff_t>(i) + 2);
    --i;
  }
  return value;
}

bool takeSwitch(std::vector<std::string>& args, const std::string& flag) {
  const auto end = std::remove(args.begin(), args.end(), flag);
  const bool given = end != args.end();
  args.erase(end, args.end());
  return given;
}

uint32_t parseUint(const std::string& flag, const std::string& text, uint32_t lo, uint32_t hi) {
  try {
    return uintFromText({flag.c_str(), double(lo), double(hi)}, text);
  } catch (const SettingsError& e) {
    throw UsageError(e.what());
  }
}

float parseFloat(const std::string& flag, const std::string& text, float lo, float hi) {
  try {
    return floatFromText({flag.c_str(), lo, hi}, text);
  } catch (const SettingsError& e) {
    throw UsageError(e.what());
  }
}

namespace {

// The flags every mode takes that are not render settings.
bool parseOtherFlag(CommonOptions& o, const std::vector<std::string>& args, size_t& i) {
  const std::string& a = args[i];
  if (a == "--validate" || a == "--validate=sync" || a == "--validate=gpu-av") {
    o.validation = a == "--validate=gpu-av" ? ValidationMode::GpuAssisted : ValidationMode::Sync;
    return true;
  }
  std::string* value = a == "--device" ? &o.device : a == "--out" ? &o.out : a == "--stats" ? &o.statsPath : nullptr;
  if (!value) return false;
  if (i + 1 >= args.size()) throw UsageError(a + " needs a value");
  *value = args[++i];
  return true;
}

}  // namespace

CommonOptions parseCommonOptions(const std::vector<std::string>& args, std::vector<std::string>* rest) {
  CommonOptions o;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    const SettingRow* row = a.rfind("--", 0) == 0 ? findSettingRow(a.substr(2)) : nullptr;
    if (row) {
      if (!row->isSwitch() && i + 1 >= args.size()) throw UsageError(a + " needs a value");
      try {
        row->parse(o.settings, row->isSwitch() ? "on" : args[++i]);
      } catch (const SettingsError& e) {
        throw UsageError(e.what());
      }
    } else if (parseOtherFlag(o, args, i)) {
      continue;
    } else if (rest && a.rfind("--", 0) == 0) {
      rest->push_back(a);
      if (i + 1 < args.size() && args[i + 1].rfind("--", 0) != 0) rest->push_back(args[++i]);
    } else {
      throw UsageError(unknownOptionMessage(a, commonOptionNames()));
    }
  }
  // What no single flag can check (paths per frame) and every range once more, as for any other source.
  if (std::optional<std::string> error = settingsError(o.settings)) throw UsageError(*error);
  return o;
}

std::vector<std::string> commonOptionNames() {
  std::vector<std::string> names = {"--device", "--validate", "--settings", "--out", "--stats"};
  for (const SettingRow& row : settingRows()) names.push_back(std::string("--") + row.flag);
  return names;
}

std::string commonOptionsHelp() {
  return settingsHelp() +
         "  --device NAME|N        Vulkan device whose name contains NAME, or number N (0-based) of\n"
         "                         `raylab devices` (for GPUs of one name on one host)\n"
         "  --validate[=sync|gpu-av]  enable the Khronos validation layer: core and synchronization\n"
         "                         checks (sync, the default), or core and GPU-assisted checks of\n"
         "                         every buffer-device-address access (gpu-av; slow); exit 4 on an\n"
         "                         error. RAYLAB_VALIDATE=1|sync|gpu-av does the same\n"
         "  --settings FILE.json   start from a screenshot sidecar (its settings and camera)\n"
         "  --out FILE.png         output image\n"
         "  --stats FILE.json      per-frame statistics as JSON\n";
}

}  // namespace raylab
