// Which bounces of a frame sort their paths: Settings::sortPolicy. `always` sorts after every bounce but the
// last, `never` after none, and `auto` decides per bounce from the stage times of earlier frames whether
// sorting after bounce b saves more in the next bounce's trace and shade than the keys, sort, reorder and
// learn it costs. Pure host logic: the decisions are a function of the frame count since the last reset
// and the stage times fed in, nothing else (no clocks, no randomness), so a seed and a cost history give
// the same decisions every time (tests/cpu/test_sort_policy.cpp).
//
// auto, per frame k since reset (k counts only frames fed back with record(); PathTracer feeds every frame
// but those with subgroup counting on):
//   k % kExplorePeriod == 0: explore sorted   (every bounce sorts, measures cost and sorted next bounce)
//   k % kExplorePeriod == 1: explore unsorted (no bounce sorts, measures the unsorted next bounce)
//   otherwise: sort after bounce b iff gain(b) = (trace + shade of b+1, unsorted) - (same, sorted) exceeds
//   cost(b) = keys + oracle-trace + sort + reorder at b, plus learn at b+1, by kMarginMs.
// Every frame updates the estimates of whatever it measured (exponential average, weight kAlpha), so the
// choice follows the view; a bounce without both measurements yet sorts (the `always` behaviour).
// With Settings::fusion the fused work is timed inside its host stage: the reorder (gather) in the next
// trace, so in `nextSorted` where it belongs; keys made in shade in shade of b, which counts towards the
// bounce before (b-1), a misattribution of 0.01-0.11 ms a bounce on the H200 that the policy accepts.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "renderer/frame_stats.h"
#include "renderer/settings.h"

namespace raylab {

struct SortPlan {
  std::vector<bool> sortAfter;       // per bounce: keys, sort and reorder after shading it
  std::vector<std::string> reasons;  // per bounce: why (shown by the UI and written to the stats)
  bool any() const;
};

class SortPolicyModel {
 public:
  static constexpr uint32_t kExplorePeriod = 256;
  static constexpr double kAlpha = 0.25;
  static constexpr double kMarginMs = 0.0;

  // The plan for the next frame of `bounces` bounces under `policy`.
  SortPlan plan(SortPolicy policy, uint32_t bounces) const;
  // Feeds back a frame rendered with `plan` (its stage times per bounce); advances the frame count.
  void record(const SortPlan& plan, const std::vector<StageTime>& stages);
  void reset();

  uint32_t framesSeen() const { return frames_; }

  struct BounceEstimate {
    double cost = -1.0;      // keys + sort + reorder at b + learn at b+1, when b sorted (-1: not measured)
    double nextSorted = -1.0;    // trace + shade of b+1 after sorting at b
    double nextUnsorted = -1.0;  // trace + shade of b+1 without sorting at b
  };
  const std::vector<BounceEstimate>& estimates() const { return estimates_; }

 private:
  uint32_t frames_ = 0;
  std::vector<BounceEstimate> estimates_;
};

}  // namespace raylab
