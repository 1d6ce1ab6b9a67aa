#include "renderer/reorder/sort_policy.h"

#include <cstdio>

namespace raylab {
namespace {

void blend(double& estimate, double sample) {
  estimate = estimate < 0.0 ? sample : (1.0 - SortPolicyModel::kAlpha) * estimate + SortPolicyModel::kAlpha * sample;
}

std::string msText(const char* what, double a, const char* rel, double b) {
  char text[96];
  std::snprintf(text, sizeof(text), "%s %.3f %s cost %.3f ms", what, a, rel, b);
  return text;
}

}  // namespace

bool SortPlan::any() const {
  for (bool s : sortAfter)
    if (s) return true;
  return false;
}

SortPlan SortPolicyModel::plan(SortPolicy policy, uint32_t bounces) const {
  SortPlan p;
  p.sortAfter.assign(bounces, false);
  p.reasons.assign(bounces, "last bounce");
  for (uint32_t b = 0; b + 1 < bounces; ++b) {
    bool s = false;
    std::string& why = p.reasons[b];
    if (policy == SortPolicy::Always) {
      s = true, why = "always";
    } else if (policy == SortPolicy::Never) {
      s = false, why = "never";
    } else if (frames_ % kExplorePeriod == 0) {
      s = true, why = "explore: sorted";
    } else if (frames_ % kExplorePeriod == 1) {
      s = false, why = "explore: unsorted";
    } else {
      BounceEstimate e = b < estimates_.size() ? estimates_[b] : BounceEstimate{};
      if (e.cost < 0.0 || e.nextSorted < 0.0 || e.nextUnsorted < 0.0) {
        s = true, why = "not measured yet";
      } else {
        double gain = e.nextUnsorted - e.nextSorted;
        s = gain > e.cost + kMarginMs;
        why = msText("gain", gain, s ? ">" : "<=", e.cost);
      }
    }
    p.sortAfter[b] = s;
  }
  return p;
}

void SortPolicyModel::record(const SortPlan& plan, const std::vector<StageTime>& stages) {
  const size_t bounces = plan.sortAfter.size();
  std::vector<double> cost(bounces, 0.0), next(bounces, 0.0);  // per bounce b: overhead at b, work of b
  for (const StageTime& st : stages) {
    if (st.bounce < 0 || size_t(st.bounce) >= bounces) continue;
    const size_t b = size_t(st.bounce);
    if (st.stage == "trace" || st.stage == "shade" || st.stage == "trace+shade") next[b] += st.ms;
    else if (st.stage == "keys" || st.stage == "oracle-trace" || st.stage == "sort" || st.stage == "reorder")
      cost[b] += st.ms;
    else if (st.stage == "learn" && b >= 1) cost[b - 1] += st.ms;  // learning the rays sorted after b-1
  }
  if (estimates_.size() < bounces) estimates_.resize(bounces);
  for (size_t b = 0; b + 1 < bounces; ++b) {
    BounceEstimate& e = estimates_[b];
    if (plan.sortAfter[b]) {
      blend(e.cost, cost[b]);
      blend(e.nextSorted, next[b + 1]);
    } else {
      blend(e.nextUnsorted, next[b + 1]);
    }
  }
  ++frames_;
}

void SortPolicyModel::reset() {
  frames_ = 0;
  estimates_.clear();
}

}  // namespace raylab
