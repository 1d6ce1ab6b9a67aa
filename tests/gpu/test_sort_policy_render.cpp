// The sort policy inside the renderer: the plan each frame follows is reported per bounce in the stats,
// `auto` warms up and explores (all sorted, then none, alternately) and then decides from what those frames measured, detailed frames
// teach it too, and the plan for a given cost history is the model's (the model's determinism for a cost
// history is tests/cpu/test_sort_policy.cpp; that sorting never changes the image is test_render_invariant.cpp).
#include <memory>

#include <gtest/gtest.h>

#include "renderer/path_tracer.h"
#include "renderer/stats_json.h"
#include "scenes/procedural.h"
#include "tests/gpu_test.h"
#include "tests/render_helpers.h"

namespace raylab::test {

class SortPolicyRender : public GpuTest {
 protected:
  // Two-point keys under the auto policy, 40x20, 4 bounces, the hall; with detailed statistics, which
  // teach the policy (its figures are what these tests read).
  static Settings autoTwoPoint() {
    Settings s = smallFrame(40, 20, 4);
    s.strategy = KeyStrategy::TwoPoint;
    s.sortPolicy = SortPolicy::Auto;
    return s;
  }
  std::unique_ptr<PathTracer> detailedTracer(const Settings& s) {
    auto tracer = std::make_unique<PathTracer>(ctx(), scene_, s, *scene_.findViewpoint("hall"));
    tracer->setDetailedStats(true);
    return tracer;
  }
  Scene scene_ = makeTemple();
};

TEST_F(SortPolicyRender, StatsReportThePlanEachFrameFollowed) {
  const Settings s = autoTwoPoint();
  std::unique_ptr<PathTracer> owned = detailedTracer(s);
  PathTracer& tracer = *owned;
  const FrameStats& f0 = tracer.renderFrame();
  ASSERT_EQ(f0.bounces.size(), 4u);
  EXPECT_TRUE(f0.bounces[0].sortedAfter);
  EXPECT_EQ(f0.bounces[0].sortReason, "warm-up: sorted (not a sample)");
  EXPECT_FALSE(f0.bounces[3].sortedAfter);
  EXPECT_EQ(f0.bounces[3].sortReason, "last bounce");
  EXPECT_GT(f0.stageTotal("sort"), 0.0);
  const FrameStats& f1 = tracer.renderFrame();
  EXPECT_FALSE(f1.bounces[1].sortedAfter);
  EXPECT_EQ(f1.bounces[1].sortReason, "warm-up: unsorted (not a sample)");
  EXPECT_EQ(f1.stageTotal("sort"), 0.0) << "a frame that sorts no bounce records no sort";
  for (uint32_t f = 2; f < 6; ++f)  // sorted and unsorted alternately until both have warm samples
    EXPECT_EQ(tracer.renderFrame().bounces[0].sortReason, f % 2 == 0 ? "explore: sorted" : "explore: unsorted") << f;
  const FrameStats& f2 = tracer.renderFrame();
  EXPECT_EQ(tracer.sortPolicy().framesSeen(), 7u) << "detailed frames teach the policy";
  for (size_t b = 0; b + 1 < f2.bounces.size(); ++b) {
    const std::string& why = f2.bounces[b].sortReason;
    EXPECT_EQ(why.rfind("gain ", 0), 0u) << "bounce " << b << ": " << why;
    EXPECT_EQ(f2.bounces[b].sortedAfter, why.find(" > cost") != std::string::npos) << why;
  }
  // The plan the renderer follows next is the model's for the history it was fed.
  SortPlan next = tracer.sortPolicy().plan(SortPolicy::Auto, 4);
  EXPECT_EQ(tracer.renderFrame().bounces[0].sortedAfter, next.sortAfter[0]);
  // A settings change that voids the measurements starts exploring again.
  Settings other = s;
  other.sortPolicy = SortPolicy::Always;
  tracer.applySettings(other);
  tracer.applySettings(s);
  EXPECT_EQ(tracer.sortPolicy().framesSeen(), 0u);
  EXPECT_EQ(tracer.renderFrame().bounces[0].sortReason, "warm-up: sorted (not a sample)");
}

TEST_F(SortPolicyRender, NeverSortsNothingAndAlwaysEveryBounceButTheLast) {
  Scene scene = makeTemple();
  Settings s = smallFrame(24, 12, 3);
  s.strategy = KeyStrategy::Fixed;
  s.sortPolicy = SortPolicy::Never;
  PathTracer tracer(ctx(), scene, s, *scene.findViewpoint("hall"));
  const FrameStats& never = tracer.renderFrame();
  EXPECT_EQ(never.stageTotal("keys") + never.stageTotal("sort") + never.stageTotal("reorder"), 0.0);
  EXPECT_EQ(never.bounces[0].sortReason, "never");
  s.sortPolicy = SortPolicy::Always;
  tracer.applySettings(s);
  const FrameStats& always = tracer.renderFrame();
  EXPECT_TRUE(always.bounces[0].sortedAfter && always.bounces[1].sortedAfter);
  EXPECT_FALSE(always.bounces[2].sortedAfter);
}

// Accuracy figures exist only where they were measured: a bounce whose rays were not keyed (auto's unsorted
// bounces) has no prediction, so its prediction error, cell-hit rate and distinct keys are null in the stats,
// never whatever the readback buffers or the path state held (they read 4e25 errors and 0.96 hit rates).
// Auto's second frame (warm-up) is unsorted right after a sorted one; then a cost history in which sorting never
// pays makes it sort nothing.
TEST_F(SortPolicyRender, UnsortedBouncesOfAutoHaveNoAccuracyFigures) {
  std::unique_ptr<PathTracer> owned = detailedTracer(autoTwoPoint());
  PathTracer& tracer = *owned;
  const FrameStats sorted = tracer.renderFrame();
  for (size_t b = 1; b < sorted.bounces.size(); ++b) {
    EXPECT_GE(sorted.bounces[b].predictionErrorMean, 0.0) << "bounce " << b << " was keyed: measured";
    EXPECT_GT(sorted.bounces[b].distinctKeys, 0) << "bounce " << b;
  }
  auto expectNoFigures = [](const FrameStats& f, const std::string& what) {
    const nlohmann::json j = toJson(f);
    ASSERT_EQ(j["bounces"].size(), 4u) << what;
    for (const nlohmann::json& b : j["bounces"]) {
      ASSERT_FALSE(b["sorted_after"].get<bool>()) << what;
      for (const char* field : {"prediction_error_mean", "prediction_error_median", "cell_hit_rate", "distinct_keys"})
        EXPECT_TRUE(!b.contains(field) || b[field].is_null()) << what << " bounce " << b["bounce"] << " " << field
                                                               << " = " << b[field];
    }
  };
  expectNoFigures(tracer.renderFrame(), "warm-up: unsorted");
  // A history in which sorting costs far more than it saves: auto sorts nothing from then on.
  SortPolicyModel& model = tracer.sortPolicy();
  model.reset();
  for (bool sorts : {true, false, true, false, true, false}) {  // warm-up, then two samples of each
    SortPlan plan;
    plan.sortAfter = {sorts, sorts, sorts, false};
    plan.reasons.assign(4, "history");
    std::vector<StageTime> stages;
    for (int b = 0; b < 4; ++b) {
      stages.push_back({"trace", b, 10.0});
      stages.push_back({"shade", b, 10.0});
      if (sorts && b < 3) stages.push_back({"sort", b, 1000.0});
    }
    model.record(plan, stages);
  }
  for (int f = 0; f < 2; ++f) {
    ASSERT_FALSE(tracer.sortPolicy().plan(SortPolicy::Auto, 4).any()) << "the history makes auto sort nothing";
    // (An unsorted frame updates only the unsorted estimates: the cost of 1000 ms stays.)
    expectNoFigures(tracer.renderFrame(), "auto sorting nothing, frame " + std::to_string(f));
  }
}

}  // namespace raylab::test
