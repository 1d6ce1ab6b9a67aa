// The one validation of Settings, whichever way they arrive: command line, window scripts, screenshot
// sidecars (`--settings`), imgui.ini and bench sweep files all end here, with the same ranges and the
// same messages, named by the command-line flag ("--bounces must be between 1 and 32, got 0"). The UI
// sliders clamp to the same ranges (settingRange, renderer/settings/settings_table.h).
#pragma once

#include <optional>
#include <stdexcept>
#include <string>

#include "renderer/settings/settings.h"

namespace raylab {

// Thrown by validateSettings and the readers below; the CLI turns it into a usage error (exit 2).
struct SettingsError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// Where a number is defined, named as on the command line. Each setting's range is in its row of the
// settings table (renderer/settings/settings_table.h).
struct NumberRange {
  const char* flag;
  double lo, hi;
};

// A number as messages write it: whole numbers in full, others to float precision (0.001 reads 0.001).
std::string formatNumber(double v);
// "FLAG must be between LO and HI, got GOT".
std::string outOfRangeMessage(const NumberRange& r, const std::string& got);
// Throws SettingsError unless lo <= v <= hi, compared as the float or integer the setting holds (so the
// documented limits themselves, e.g. --ema-alpha 0.001, are accepted).
void checkFloat(const NumberRange& r, double v, const std::string& text);
void checkUint(const NumberRange& r, double v, const std::string& text);
// A flag's text as a number within r, or SettingsError: "--bounces expects a whole number, got 'x'",
// "--ema-alpha expects a finite number, got 'nan'", or the range's message.
uint32_t uintFromText(const NumberRange& r, const std::string& text);
float floatFromText(const NumberRange& r, const std::string& text);

// A locked heatmap range must be a non-empty interval: "--heatmap-range min (5) must be below max (2)".
void checkHeatmapRange(const HeatmapRange& r);

// The first problem of `s` (a field outside its range, in the settings table's order; too many paths per
// frame; a tile sort without compaction), or nothing.
std::optional<std::string> settingsError(const Settings& s);
// Throws SettingsError with settingsError's message.
void validateSettings(const Settings& s);

}  // namespace raylab
