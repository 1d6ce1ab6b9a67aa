// The sort policy (renderer/reorder/sort_policy.h): always/never are fixed plans; auto explores, then sorts
// after a bounce exactly when the measured gain of the next bounce exceeds the measured cost, and its
// decisions are a function of the cost history alone (the same history gives the same plans).
#include <gtest/gtest.h>

#include "renderer/reorder/sort_policy.h"

namespace raylab {
namespace {

// Stage times of one frame of `bounces` bounces rendered with `plan`: trace+shade of bounce b is
// `unsorted[b]` unless bounce b-1 sorted, then `sorted[b]`; each sorted bounce costs `cost`.
std::vector<StageTime> frameTimes(const SortPlan& plan, const std::vector<double>& unsorted,
                                  const std::vector<double>& sorted, double cost) {
  std::vector<StageTime> st;
  for (size_t b = 0; b < plan.sortAfter.size(); ++b) {
    bool after = b > 0 && plan.sortAfter[b - 1];
    st.push_back({"trace", int(b), 0.75 * (after ? sorted[b] : unsorted[b])});
    st.push_back({"shade", int(b), 0.25 * (after ? sorted[b] : unsorted[b])});
    if (plan.sortAfter[b]) {
      st.push_back({"keys", int(b), 0.1 * cost});
      st.push_back({"sort", int(b), 0.3 * cost});
      st.push_back({"reorder", int(b), 0.6 * cost});
    }
  }
  st.push_back({"accumulate", -1, 0.04});
  return st;
}

TEST(SortPolicy, AlwaysAndNeverAreFixed) {
  SortPolicyModel m;
  SortPlan a = m.plan(SortPolicy::Always, 4), n = m.plan(SortPolicy::Never, 4);
  EXPECT_EQ(a.sortAfter, (std::vector<bool>{true, true, true, false}));  // never after the last bounce
  EXPECT_EQ(n.sortAfter, (std::vector<bool>{false, false, false, false}));
  EXPECT_EQ(a.reasons[0], "always");
  EXPECT_EQ(n.reasons[1], "never");
}

TEST(SortPolicy, AutoExploresThenSortsOnlyWhereItPays) {
  SortPolicyModel m;
  // Sorting after bounce 0 saves 1.0 ms on bounce 1, after bounce 1 only 0.2 ms on bounce 2, after
  // bounce 2 saves 0.7 ms; each sort costs 0.5 ms.
  const std::vector<double> unsorted{3.0, 3.0, 2.0, 1.5}, sorted{3.0, 2.0, 1.8, 0.8};
  SortPlan p0 = m.plan(SortPolicy::Auto, 4);
  EXPECT_EQ(p0.sortAfter, (std::vector<bool>{true, true, true, false}));
  EXPECT_EQ(p0.reasons[0], "explore: sorted");
  m.record(p0, frameTimes(p0, unsorted, sorted, 0.5));
  SortPlan p1 = m.plan(SortPolicy::Auto, 4);
  EXPECT_FALSE(p1.any());
  EXPECT_EQ(p1.reasons[0], "explore: unsorted");
  m.record(p1, frameTimes(p1, unsorted, sorted, 0.5));
  for (int f = 0; f < 20; ++f) {
    SortPlan p = m.plan(SortPolicy::Auto, 4);
    EXPECT_EQ(p.sortAfter, (std::vector<bool>{true, false, true, false})) << "frame " << f + 2;
    m.record(p, frameTimes(p, unsorted, sorted, 0.5));
  }
  SortPlan p = m.plan(SortPolicy::Auto, 4);
  EXPECT_EQ(p.reasons[1], "gain 0.200 <= cost 0.500 ms");
  EXPECT_EQ(p.reasons[0], "gain 1.000 > cost 0.500 ms");
}

TEST(SortPolicy, AutoNeverSortsWhenSortingCostsMoreThanItSaves) {
  SortPolicyModel m;
  const std::vector<double> unsorted{3.0, 3.0, 2.0, 1.5}, sorted{3.0, 2.5, 1.7, 1.2};
  for (int f = 0; f < 2; ++f) {
    SortPlan p = m.plan(SortPolicy::Auto, 4);
    m.record(p, frameTimes(p, unsorted, sorted, 0.61));
  }
  EXPECT_FALSE(m.plan(SortPolicy::Auto, 4).any());
  // It explores again after kExplorePeriod frames.
  for (uint32_t f = 2; f < SortPolicyModel::kExplorePeriod; ++f) {
    SortPlan p = m.plan(SortPolicy::Auto, 4);
    EXPECT_FALSE(p.any()) << f;
    m.record(p, frameTimes(p, unsorted, sorted, 0.61));
  }
  EXPECT_EQ(m.plan(SortPolicy::Auto, 4).reasons[0], "explore: sorted");
}

TEST(SortPolicy, AutoIsDeterministicForACostHistory) {
  // A noisy but fixed cost history (a seeded LCG): two models fed the same history plan the same frames.
  auto run = [](uint32_t seed) {
    SortPolicyModel m;
    std::vector<std::vector<bool>> plans;
    uint32_t rng = seed;
    auto noise = [&] {
      rng = rng * 1664525u + 1013904223u;
      return 0.3 * double(rng >> 8) / double(1u << 24);
    };
    for (int f = 0; f < 300; ++f) {
      SortPlan p = m.plan(SortPolicy::Auto, 5);
      plans.push_back(p.sortAfter);
      std::vector<double> unsorted{3.0, 2.9 + noise(), 2.1 + noise(), 1.4 + noise(), 1.0},
          sorted{3.0, 2.3 + noise(), 1.9 + noise(), 1.3 + noise(), 0.9};
      m.record(p, frameTimes(p, unsorted, sorted, 0.3 + noise()));
    }
    return plans;
  };
  EXPECT_EQ(run(7), run(7));
  EXPECT_NE(run(7), run(8)) << "the history must matter";
}

TEST(SortPolicy, ResetForgetsWhatWasMeasured) {
  SortPolicyModel m;
  SortPlan p = m.plan(SortPolicy::Auto, 3);
  m.record(p, frameTimes(p, {1, 1, 1}, {1, 1, 1}, 0.1));
  EXPECT_EQ(m.framesSeen(), 1u);
  m.reset();
  EXPECT_EQ(m.framesSeen(), 0u);
  EXPECT_TRUE(m.estimates().empty());
  EXPECT_EQ(m.plan(SortPolicy::Auto, 3).reasons[0], "explore: sorted");
}

}  // namespace
}  // namespace raylab
