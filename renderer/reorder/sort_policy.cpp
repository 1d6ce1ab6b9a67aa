#include "renderer/reorder/sort_policy.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "renderer/stages.h"

namespace raylab {
namespace {

constexpr double kEffectiveSamples = (2.0 - SortPolicyModel::kAlpha) / SortPolicyModel::kAlpha;  // 7

std::string decisionText(double gain, bool sorts, double cost, double margin) {
  char text[128];
  // "gain X > cost Y ms" first: tests/cli/gpu/window_matches_headless.sh reads it.
  int n = std::snprintf(text, sizeof(text), "gain %.3f %s cost %.3f ms", gain, sorts ? ">" : "<=", cost);
  if (margin >= 0.0005) std::snprintf(text + n, sizeof(text) - n, " (+ margin %.3f ms)", margin);
  return text;
}

}  // namespace

bool SortPlan::any() const {
  for (bool s : sortAfter)
    if (s) return true;
  return false;
}

// The first samples are averaged alike (weight 1/n), later ones exponentially (kAlpha), so a warm sample
// does not sit under the first one's weight; the variance follows with the same weight.
void SortPolicyModel::Arm::add(double sample, uint32_t frame) {
  ++samples;
  lastFrame = frame;
  if (samples == 1) {
    mean = sample, var = 0.0;
    return;
  }
  const double w = std::max(kAlpha, 1.0 / samples), d = sample - mean;
  mean += w * d;
  var = (1.0 - w) * (var + w * d * d);
}

// The weighted variance is the population one: divided by n - 1 of the (at most kEffectiveSamples) samples
// it stands for, it is the squared standard error of the mean.
double SortPolicyModel::Arm::sem() const {
  const double n = std::min(double(samples), kEffectiveSamples);
  return n > 1.0 ? std::sqrt(var / (n - 1.0)) : 0.0;
}

// Sort after b iff its gain exceeds its cost by the margin; `why` says so with the numbers, `close` whether
// the difference is within the margin (either way).
bool SortPolicyModel::decide(uint32_t b, std::string& why, bool& close) const {
  const BounceEstimate& e = estimates_[b];
  const double cost = e.cost.mean, gain = e.unsorted.mean - (e.sorted.mean - cost);
  const double margin = kSigmas * std::hypot(e.sorted.sem(), e.unsorted.sem());
  const bool sorts = gain > cost + margin;
  close = margin > 0.0 && std::abs(gain - cost) <= margin;
  why = decisionText(gain, sorts, cost, margin);
  return sorts;
}

SortPlan SortPolicyModel::plan(SortPolicy policy, uint32_t bounces) const {
  SortPlan p;
  p.sortAfter.assign(bounces, false);
  p.reasons.assign(bounces, "last bounce");
  for (uint32_t b = 0; b + 1 < bounces; ++b) {
    bool s = false;
    std::string& why = p.reasons[b];
    const BounceEstimate e = b < estimates_.size() ? estimates_[b] : BounceEstimate{};
    if (policy == SortPolicy::Always) {
      s = true, why = "always";
    } else if (policy == SortPolicy::Never) {
      s = false, why = "never";
    } else if (frames_ < kColdFrames) {
      p.measuring = true;
      s = frames_ % 2 == 0, why = s ? "warm-up: sorted (not a sample)" : "warm-up: unsorted (not a sample)";
    } else if (e.sorted.samples < kMinSamples || e.unsorted.samples < kMinSamples) {
      // The arm that lacks samples; both alternately.
      const bool sortedLacks = e.sorted.samples < kMinSamples, unsortedLacks = e.unsorted.samples < kMinSamples;
      p.measuring = true;
      s = sortedLacks && (!unsortedLacks || frames_ % 2 == 0);
      why = s ? "explore: sorted" : "explore: unsorted";
    } else {
      std::string decision;
      bool close = false;
      const bool sorts = decide(b, decision, close);
      const Arm& other = sorts ? e.unsorted : e.sorted;
      const uint32_t age = frames_ - other.lastFrame, every = close ? kNoisyStaleFrames : kStaleFrames;
      // Probes fall on frames that are multiples of their interval, for every bounce alike, so one frame in
      // `every` at most probes, all the bounces that are due in it: probed each on its own schedule, the
      // bounces put a probe in 28-31% of the frames of a noisy history (tests/cpu/test_sort_policy.cpp,
      // AutoProbesShareFrames), and a bench cell's median frame could be a probing one. Tried and not kept:
      // doubling a bounce's interval after each probe that confirmed its decision (up to 64 frames): its
      // stale arm then held a wrong decision in that noisy history (bounce 0 sorted at frame 45: gain 0.225
      // > cost 0.174 + margin 0.049 ms), while on the H200 the miss it aimed at is within the cells' noise
      // (docs/results/h200-scale-paths/policy-matrix/shared-probes).
      if (age >= every && frames_ % every == 0) {
        p.measuring = true;
        s = !sorts;
        why = std::string(s ? "probe: sorted" : "probe: unsorted") + ", measured " + std::to_string(age) +
              " frames ago (" + decision + ")";
      } else {
        s = sorts, why = decision;
      }
    }
    p.sortAfter[b] = s;
  }
  return p;
}

void SortPolicyModel::record(const SortPlan& plan, const std::vector<StageTime>& stages) {
  const uint32_t frame = frames_++;
  if (frame < kColdFrames) return;  // first use: not comparable with what follows
  const size_t bounces = plan.sortAfter.size();
  std::vector<double> cost(bounces, 0.0), next(bounces, 0.0);  // per bounce b: overhead at b, work of b
  for (const StageTime& st : stages) {
    if (st.bounce < 0 || size_t(st.bounce) >= bounces) continue;
    const size_t b = size_t(st.bounce);
    const StageInfo* info = findStage(st.stage);
    if (!info) continue;
    if (info->role == StageRole::PathWork) next[b] += st.ms;
    else if (info->role == StageRole::Reorder) cost[b] += st.ms;
    else if (info->role == StageRole::LearnBefore && b >= 1) cost[b - 1] += st.ms;  // the rays sorted after b-1
  }
  if (estimates_.size() < bounces) estimates_.resize(bounces);
  for (size_t b = 0; b + 1 < bounces; ++b) {
    BounceEstimate& e = estimates_[b];
    if (plan.sortAfter[b]) {
      e.cost.add(cost[b], frame);
      e.sorted.add(cost[b] + next[b + 1], frame);
    } else {
      e.unsorted.add(next[b + 1], frame);
    }
  }
}

void SortPolicyModel::reset() {
  frames_ = 0;
  estimates_.clear();
}

}  // namespace raylab
