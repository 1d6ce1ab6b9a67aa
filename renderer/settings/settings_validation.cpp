#include "renderer/settings/settings_validation.h"

#include "renderer/settings/settings_table.h"
#include "shaders/sort_types.h"

#include <cerrno>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace raylab {
std::string formatNumber(double v) {
  char text[40];
  // Whole numbers in full (4294967295, not 4.294967e+09); others to float precision.
  if (v == std::floor(v) && std::abs(v) < 1e15) std::snprintf(text, sizeof(text), "%.0f", v);
  else std::snprintf(text, sizeof(text), "%.7g", v);
  return text;
}

namespace {

std::string number(double v) { return formatNumber(v); }

// A double as the float a setting holds; beyond float's range it is infinite (never converted: UB).
float asFloat(double v) {
  if (std::abs(v) > double(FLT_MAX)) return v > 0 ? INFINITY : -INFINITY;
  return static_cast<float>(v);
}

}  // namespace

std::string outOfRangeMessage(const NumberRange& r, const std::string& got) {
  return std::string(r.flag) + " must be between " + number(r.lo) + " and " + number(r.hi) +
         ", got " + got;
}

void checkFloat(const NumberRange& r, double v, const std::string& text) {
  float f = asFloat(v);
  if (!(f >= asFloat(r.lo) && f <= asFloat(r.hi))) throw SettingsError(outOfRangeMessage(r, text));
}

void checkUint(const NumberRange& r, double v, const std::string& text) {
  if (!(v >= r.lo && v <= r.hi) || v != std::floor(v)) {
    if (v == std::floor(v) || !std::isfinite(v)) throw SettingsError(outOfRangeMessage(r, text));
    throw SettingsError(std::string(r.flag) + " expects a whole number, got " + text);
  }
}

uint32_t uintFromText(const NumberRange& r, const std::string& text) {
  if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos)
    throw SettingsError(std::string(r.flag) + " expects a whole number, got '" + text + "'");
  errno = 0;
  unsigned long long v = std::strtoull(text.c_str(), nullptr, 10);
  if (errno == ERANGE || v < r.lo || v > r.hi) throw SettingsError(outOfRangeMessage(r, text));
  return static_cast<uint32_t>(v);
}

float floatFromText(const NumberRange& r, const std::string& text) {
  char* end = nullptr;
  errno = 0;
  double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE || !std::isfinite(v))
    throw SettingsError(std::string(r.flag) + " expects a finite number, got '" + text + "'");
  checkFloat(r, v, text);  // compared as floats: the limits themselves are accepted
  return static_cast<float>(v);
}

void checkHeatmapRange(const HeatmapRange& r) {
  const NumberRange lo{"--heatmap-range min", 0, SettingLimits::kMaxHeatmapValue};
  const NumberRange hi{"--heatmap-range max", 0, SettingLimits::kMaxHeatmapValue};
  checkFloat(lo, r.min, number(r.min));
  checkFloat(hi, r.max, number(r.max));
  if (!(r.min < r.max))
    throw SettingsError("--heatmap-range min (" + number(r.min) + ") must be below max (" + number(r.max) + ")");
}

std::optional<std::string> settingsError(const Settings& s) {
  try {
    for (const SettingRow& row : settingRows()) row.check(s);
  } catch (const SettingsError& e) {
    return e.what();
  }
  // A sort within tiles leaves the live paths of each tile in front of its finished ones, not all live paths
  // in front of all finished ones: the reorder's live prefix then needs the finished paths packed out first.
  if (s.sorts() && s.sort == SortAlgorithm::Tile && (!s.compacts() || s.fusesKeys()))
    return "--sort tile sorts each tile of " + std::to_string(gpu::uint(SORT_BITONIC_TILE)) +
           " paths alone and needs the finished paths packed out before it: use --compaction shade with the compute "
           "tracer, and --fusion none or gather";
  // Auto weighs each bounce's path work against its sort's cost (SortPolicyModel::record): bounces traced in
  // one loop have no time of their own.
  if (s.sorts() && s.loopsBounces() && s.sortPolicy == SortPolicy::Auto)
    return "--trace-shade loop runs the bounces after the last sort in one dispatch, which leaves --sort-policy auto "
           "no time per bounce to weigh: use --sort-policy always or never with it, or --trace-shade fused";
  // Path state is allocated per path: the product must stay within what a device can hold (and a uint32).
  uint64_t paths = uint64_t(s.width) * s.height * s.sppPerFrame;
  if (paths > SettingLimits::kMaxPathsPerFrame)
    return "--size x --spp gives " + std::to_string(paths) + " paths per frame (" + std::to_string(s.width) + "x" +
           std::to_string(s.height) + " at " + std::to_string(s.sppPerFrame) + " spp); at most " +
           std::to_string(SettingLimits::kMaxPathsPerFrame) + " (8192x8192 at 1 spp)";
  return std::nullopt;
}

void validateSettings(const Settings& s) {
  if (std::optional<std::string> e = settingsError(s)) throw SettingsError(*e);
}

}  // namespace raylab
