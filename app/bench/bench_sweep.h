// The benchmark's sweep: which (scene, viewpoint) cases, and which method settings to run on each.
// Parsed from flags or a sweep file of `flag = value` lines (same names as the flags, without dashes).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "app/bench/bench_rounds.h"
#include "app/cli_options.h"

namespace raylab {

struct BenchCase {
  std::string scene;
  std::string view;  // empty: the scene's first viewpoint
};

struct BenchCell {
  size_t caseIndex = 0;
  Settings settings;
  std::string label;  // e.g. "fixed/radix grid=auto clamp=off"
};

struct BenchPlan {
  CommonOptions common;  // base settings, device, validation
  std::vector<BenchCase> cases;
  std::vector<BenchCell> cells;  // every case x method combination, baselines first
  uint32_t timedFrames = 8;
  uint32_t warmupFrames = 2;
  uint32_t referenceSpp = 64;
  uint32_t rounds = kDefaultRounds;  // every cell once per round, in another order each round (bench_rounds.h)
  bool detailFrame = true;  // one untimed counting/readback frame per cell (SIMT, warp efficiency, accuracy)
  bool charts = true;       // draw the charts at the end (app/bench/bench_charts.py); --no-charts: the CSV only
  std::string outDir = "bench-out";
  // --camera-path FILE|builtin:NAME: every cell replays the path instead of timing still frames
  // (app/bench/bench_path.h); empty: still frames. --frames caps its frames (pathFramesCap).
  std::string cameraPath;
  std::optional<uint32_t> pathFramesCap;
};

// Throws UsageError for unknown names or values.
BenchPlan parseBenchPlan(const std::vector<std::string>& args);
std::string benchHelp();
// "a,b,,c" -> {"a", "b", "c"}: the comma lists of the sweep flags (and of `raylab study`'s).
std::vector<std::string> splitList(const std::string& text);

}  // namespace raylab
