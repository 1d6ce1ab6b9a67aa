// The sort policy inside the renderer: the plan each frame follows is reported per bounce in the stats,
// `auto` explores (all sorted, then none) and then decides from what those frames measured, detailed frames
// teach it too, and the plan for a given cost history is the model's (the model's determinism for a cost
// history is tests/cpu/test_sort_policy.cpp; that sorting never changes the image is test_render_invariant.cpp).
#include <gtest/gtest.h>

#include "renderer/path_tracer.h"
#include "scenes/procedural.h"
#include "tests/gpu_test.h"
#include "tests/render_helpers.h"

namespace raylab::test {

class SortPolicyRender : public GpuTest {};

TEST_F(SortPolicyRender, StatsReportThePlanEachFrameFollowed) {
  Scene scene = makeTemple();
  Settings s = smallFrame(40, 20, 4);
  s.strategy = KeyStrategy::TwoPoint;
  s.sortPolicy = SortPolicy::Auto;
  PathTracer tracer(ctx(), scene, s, *scene.findViewpoint("hall"));
  tracer.setDetailedStats(true);
  const FrameStats& f0 = tracer.renderFrame();
  ASSERT_EQ(f0.bounces.size(), 4u);
  EXPECT_TRUE(f0.bounces[0].sortedAfter);
  EXPECT_EQ(f0.bounces[0].sortReason, "explore: sorted");
  EXPECT_FALSE(f0.bounces[3].sortedAfter);
  EXPECT_EQ(f0.bounces[3].sortReason, "last bounce");
  EXPECT_GT(f0.stageTotal("sort"), 0.0);
  const FrameStats& f1 = tracer.renderFrame();
  EXPECT_FALSE(f1.bounces[1].sortedAfter);
  EXPECT_EQ(f1.bounces[1].sortReason, "explore: unsorted");
  EXPECT_EQ(f1.stageTotal("sort"), 0.0) << "a frame that sorts no bounce records no sort";
  const FrameStats& f2 = tracer.renderFrame();
  EXPECT_EQ(tracer.sortPolicy().framesSeen(), 3u) << "detailed frames teach the policy";
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
  EXPECT_EQ(tracer.renderFrame().bounces[0].sortReason, "explore: sorted");
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

}  // namespace raylab::test
