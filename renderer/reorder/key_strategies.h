// Every key strategy's facts, declared once: its name (command line, JSON, imgui.ini, CSV labels), its id in
// the shaders (RL_KEY_*, specialization constant 1 of the key stage) and which settings it reads. The
// settings code, the key stage, the heatmap rules, the Method panel, the speed-accuracy book and the bench
// sweep all ask this table; none keeps a list of its own (issue 19: three lists disagreed on which strategies
// read the fixed length).
#pragma once

#include <cstddef>
#include <cstdint>

#include "renderer/settings/settings.h"
#include "shaders/key_types.h"

namespace raylab {

struct KeyStrategyInfo {
  KeyStrategy strategy;
  const char* name;
  uint32_t shaderId;       // RL_KEY_*: the switch in shaders/keys.glsl
  bool usesGrid;           // its key is made of grid cells: the grid and camera clamp settings apply
  bool readsFixedLength;   // reads fixedFactor: as its length (fixed, two-point), or where it knows none
                           // (the length caches before they learn a cell, the oracle on a miss)
  bool learnsLengths;      // keeps a length cache of (cell, octant): learnEvery, the cache heatmaps
  bool readsEmaAlpha;      // the exponential moving average's weight
  bool samplesGaussian;    // samples N(mean, sigma): the reset variance and outlier settings
};

inline constexpr KeyStrategyInfo kKeyStrategies[] = {
    // strategy                     name                shader id                grid   fixed  cache  alpha  gauss
    {KeyStrategy::None,            "none",             RL_KEY_NONE,             false, false, false, false, false},
    {KeyStrategy::DeadLast,        "dead-last",        RL_KEY_DEAD_LAST,        false, false, false, false, false},
    {KeyStrategy::Fixed,           "fixed",            RL_KEY_FIXED,            true,  true,  false, false, false},
    {KeyStrategy::Average,         "average",          RL_KEY_AVERAGE,          true,  true,  true,  false, false},
    {KeyStrategy::Ema,             "ema",              RL_KEY_EMA,              true,  true,  true,  true,  false},
    {KeyStrategy::Gaussian,        "gaussian",         RL_KEY_GAUSSIAN,         true,  true,  true,  false, true},
    {KeyStrategy::Origin,          "origin",           RL_KEY_ORIGIN,           true,  false, false, false, false},
    {KeyStrategy::Direction,       "direction",        RL_KEY_DIRECTION,        true,  false, false, false, false},
    {KeyStrategy::OriginDirection, "origin-direction", RL_KEY_ORIGIN_DIRECTION, true,  false, false, false, false},
    {KeyStrategy::TwoPoint,        "two-point",        RL_KEY_TWO_POINT,        true,  true,  false, false, false},
    {KeyStrategy::Oracle,          "oracle",           RL_KEY_ORACLE,           true,  true,  false, false, false},
};

// The table is in enum order and every row's shader id is the enum's value: checked here, for every row.
constexpr bool keyStrategyTableInOrder() {
  for (size_t i = 0; i < std::size(kKeyStrategies); ++i)
    if (static_cast<size_t>(kKeyStrategies[i].strategy) != i || kKeyStrategies[i].shaderId != i) return false;
  return true;
}
static_assert(keyStrategyTableInOrder(), "kKeyStrategies must list every KeyStrategy in order, with its RL_KEY_* id");
static_assert(std::size(kKeyStrategies) == static_cast<size_t>(KeyStrategy::Oracle) + 1, "a strategy has no row");

constexpr const KeyStrategyInfo& strategyInfo(KeyStrategy s) { return kKeyStrategies[static_cast<size_t>(s)]; }

}  // namespace raylab
