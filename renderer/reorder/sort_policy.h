// Which bounces of a frame sort their paths: Settings::sortPolicy. `always` sorts after every bounce but the
// last, `never` after none, and `auto` decides per bounce from the stage times of earlier frames whether
// sorting after bounce b saves more in the next bounce's trace and shade than the keys, sort, reorder and
// learn it costs. Pure host logic: the decisions are a function of the frame count since the last reset
// and the stage times fed in, nothing else (no clocks, no randomness), so a seed and a cost history give
// the same decisions every time (tests/cpu/test_sort_policy.cpp).
//
// auto compares like with like. Per bounce b it keeps two arms, each an exponential average (weight
// kAlpha) of warm samples with their spread: sorted = cost(b) + work of b+1 when b sorted, unsorted = work
// of b+1 when it did not (work: trace + shade or trace+shade; cost: keys + oracle-trace + sort + reorder at
// b, learn at b+1). Per frame k since reset (k counts frames fed back with record(); PathTracer feeds every
// frame but those with subgroup counting on):
//   k < kColdFrames: warm-up, sorted then unsorted; not samples. The first frame after a reset pays for
//     first use (pipelines, caches, clocks): H200 Sponza 4096x2048, the old policy compared that cold
//     sorted frame 0 with a warm unsorted frame 1, concluded sorting did not pay, and kept that for 256
//     frames (auto 28.65 ms against always 26.51).
//   then, while an arm of b has fewer than kMinSamples samples: explore, sorted on even k, unsorted on odd.
//   otherwise: sort iff gain = unsorted - (sorted - cost) exceeds cost by kSigmas standard errors of the
//     difference (the margin, from the measured spread; 0 for a noiseless history). The arm not taken is
//     measured again (the bounce flips for one frame, "probe") once its last sample is kStaleFrames old,
//     or kNoisyStaleFrames when the difference is within the margin (flipping then costs little), on the
//     first frame after that whose count is a multiple of that interval: the bounces probe in shared frames.
// Attribution when stages fuse: with Settings::fusion gather the reorder is timed inside the next trace,
// so in the sorted arm's work of b+1, which the decision adds to cost anyway (the reason text then shows a
// smaller gain and cost, the same difference). With fused trace+shade a sort after b makes b+1 split
// (gathering trace, learn, shade): its time is that arm's work of b+1, the unsorted arm's the fused one,
// which is the real difference. Keys made in shade (fusion keys/both) are timed in shade of b and so count
// towards the arms of b-1, a misattribution of 0.01-0.11 ms a bounce on the H200 that the policy accepts.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "renderer/frame_stats.h"
#include "renderer/settings/settings.h"

namespace raylab {

struct SortPlan {
  std::vector<bool> sortAfter;       // per bounce: keys, sort and reorder after shading it
  std::vector<std::string> reasons;  // per bounce: why (shown by the UI and written to the stats)
  // auto only: some bounce departs from the decision to measure an arm (warm-up, explore or probe). A bench
  // times auto from the first frame whose plan does not measure, and takes its counting frame from such a
  // frame: a frame that explores describes the arm it measures, not the policy (issue 34).
  bool measuring = false;
  bool any() const;
};

class SortPolicyModel {
 public:
  static constexpr uint32_t kColdFrames = 2;        // frames after a reset that are not samples
  static constexpr uint32_t kMinSamples = 2;        // warm samples each arm needs before deciding
  static constexpr uint32_t kStaleFrames = 16;      // the arm not taken is measured again this old
  static constexpr uint32_t kNoisyStaleFrames = 4;  // ... or this old when the decision is within the margin
  static constexpr double kAlpha = 0.25;
  static constexpr double kSigmas = 2.0;            // the margin, in standard errors of gain - cost

  // The plan for the next frame of `bounces` bounces under `policy`.
  SortPlan plan(SortPolicy policy, uint32_t bounces) const;
  // Feeds back a frame rendered with `plan` (its stage times per bounce); advances the frame count.
  void record(const SortPlan& plan, const std::vector<StageTime>& stages);
  void reset();

  uint32_t framesSeen() const { return frames_; }

  struct Arm {
    double mean = -1.0;  // ms (-1: not measured)
    double var = 0.0;    // exponentially weighted variance of the samples
    uint32_t samples = 0;
    uint32_t lastFrame = 0;  // frame count when last measured
    void add(double sample, uint32_t frame);
    double sem() const;  // standard error of the mean (effective sample count capped by kAlpha)
  };
  struct BounceEstimate {
    Arm cost;            // keys + sort + reorder at b + learn at b+1, when b sorted
    Arm sorted;          // cost + trace + shade of b+1 after sorting at b
    Arm unsorted;        // trace + shade of b+1 without sorting at b
  };
  const std::vector<BounceEstimate>& estimates() const { return estimates_; }

 private:
  bool decide(uint32_t b, std::string& why, bool& close) const;
  uint32_t frames_ = 0;
  std::vector<BounceEstimate> estimates_;
};

}  // namespace raylab
