// Render flags applied on top of existing Settings, with exactly the CLI's validation. parseCommonOptions
// always starts from default Settings; the window needs "change this one field of what I have" (a script's
// `set strategy gaussian`, command-line flags over the settings remembered in imgui.ini, flags after
// `--settings FILE.json`). Each flag is a row of the settings table (renderer/settings/settings_table.h).
#pragma once

#include <string>
#include <vector>

#include "renderer/settings/settings.h"

namespace raylab {

// Applies one flag, named without dashes ("strategy", "heatmap-bounce"), with its value. Switches
// ("count-simt") take on/off/true/false/1/0; "clamp off" turns clamping off. Throws UsageError.
void applySettingFlag(Settings& settings, const std::string& name, const std::string& value);

// Applies every render flag in `args` (CLI spelling, "--strategy gaussian ...") to `base`; only the fields
// those flags name change. Flags that are not render settings (--out, --device, ...) are skipped; unknown
// ones throw UsageError, or with `skipUnknown` are skipped with their value by parseCommonOptions's rule
// (the next argument is a value unless it starts with "--").
Settings overlaySettingFlags(const Settings& base, const std::vector<std::string>& args, bool skipUnknown = false);

// Names (without dashes) of the flags that write Settings, for messages and tests.
std::vector<std::string> settingFlagNames();

}  // namespace raylab
