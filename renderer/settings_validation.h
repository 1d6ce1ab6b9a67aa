// The one validation of Settings, whichever way they arrive: command line, window scripts, screenshot
// sidecars (`--settings`), imgui.ini and bench sweep files all end here, with the same ranges and the
// same messages, named by the command-line flag ("--bounces must be between 1 and 32, got 0"). The UI
// sliders clamp to the same SettingLimits.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>

#include "renderer/settings.h"

namespace raylab {

// Thrown by validateSettings and the readers below; the CLI turns it into a usage error (exit 2).
struct SettingsError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// Where a number is defined, named as on the command line.
struct NumberRange {
  const char* flag;
  double lo, hi;
};
namespace ranges {
using L = SettingLimits;
inline constexpr NumberRange width{"--size width", 1, L::kMaxSize};
inline constexpr NumberRange height{"--size height", 1, L::kMaxSize};
inline constexpr NumberRange bounces{"--bounces", 1, L::kMaxBounces};
inline constexpr NumberRange spp{"--spp", 1, L::kMaxSpp};
inline constexpr NumberRange frames{"--frames", 1, L::kMaxFrames};
inline constexpr NumberRange seed{"--seed", 0, 4294967295.0};
inline constexpr NumberRange exposure{"--exposure", 0, L::kMaxExposure};
inline constexpr NumberRange gridCells{"--grid", 1, L::kMaxGridCellsPerAxis};
inline constexpr NumberRange gridAutoCells{"--grid (automatic cells)", 1, L::kMaxGridCellsPerAxis};
inline constexpr NumberRange clamp{"--clamp", 0, L::kMaxClampDistance};
inline constexpr NumberRange fixedFactor{"--fixed-factor", L::kMinFixedFactor, L::kMaxFixedFactor};
inline constexpr NumberRange emaAlpha{"--ema-alpha", L::kMinEmaAlpha, L::kMaxEmaAlpha};
inline constexpr NumberRange gaussOutlier{"--gauss-outlier", 0, L::kMaxGaussOutlier};
inline constexpr NumberRange gaussReset{"--gauss-reset", 0, 3.0e38};
inline constexpr NumberRange sortBits{"--sort-bits", 0, 32};
inline constexpr NumberRange learnEvery{"--learn-every", 1, 64};
inline constexpr NumberRange heatmapBounce{"--heatmap-bounce", 0, L::kMaxBounces - 1};
inline constexpr NumberRange heatmapRangeMin{"--heatmap-range min", 0, L::kMaxHeatmapValue};
inline constexpr NumberRange heatmapRangeMax{"--heatmap-range max", 0, L::kMaxHeatmapValue};
}  // namespace ranges

// A number as messages write it: whole numbers in full, others to float precision (0.001 reads 0.001).
std::string formatNumber(double v);
// "FLAG must be between LO and HI, got GOT".
std::string outOfRangeMessage(const NumberRange& r, const std::string& got);
// Throws SettingsError unless lo <= v <= hi, compared as the float or integer the setting holds (so the
// documented limits themselves, e.g. --ema-alpha 0.001, are accepted).
void checkFloat(const NumberRange& r, double v, const std::string& text);
void checkUint(const NumberRange& r, double v, const std::string& text);

// A locked heatmap range must be a non-empty interval: "--heatmap-range min (5) must be below max (2)".
void checkHeatmapRange(const HeatmapRange& r);

// The first problem of `s` (a field outside its range, too many paths per frame), or nothing.
std::optional<std::string> settingsError(const Settings& s);
// Throws SettingsError with settingsError's message.
void validateSettings(const Settings& s);

}  // namespace raylab
