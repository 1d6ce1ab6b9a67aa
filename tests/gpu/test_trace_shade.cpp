// Settings::traceShade fused: shade.comp traces the ray it loaded instead of reading the trace's hit record,
// in one dispatch ("trace+shade") wherever nothing between trace and shade reads the hits. It renders the
// split image bit for bit, counts the same rays per bounce, and leaves split exactly the bounces that need it.
#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "tests/gpu_test.h"
#include "tests/render_helpers.h"
#include "scenes/procedural.h"

namespace raylab::test {
namespace {

class TraceShadeRender : public GpuTest {};

int stageCount(const FrameStats& s, const std::string& stage) {
  return static_cast<int>(std::count_if(s.stages.begin(), s.stages.end(), [&](const StageTime& t) { return t.stage == stage; }));
}

// Unsorted with and without compaction, and sorted: a strategy with and one without a length cache (which
// learns from the sorted rays' hits, so those bounces stay split), each reorder and keys in shade, under each
// of `policies`, over two frames: `traceShade` renders the split image bit for bit.
void expectTheSplitImage(const VulkanContext& ctx, TraceShade traceShade, std::initializer_list<SortPolicy> policies) {
  Scene scene = makeTemple();
  const Viewpoint& view = *scene.findViewpoint("openings");
  Settings base = smallFrame(33, 17, 5);
  base.frames = 2;
  const std::vector<glm::vec3> split = renderRadiance(ctx, scene, base, view);
  ASSERT_GT(moments(split).mean, 0.0);
  const std::string how = toString(traceShade);
  for (Compaction compaction : {Compaction::None, Compaction::Shade}) {
    Settings s = base;
    s.compaction = compaction;
    s.traceShade = traceShade;
    expectSameImage(renderRadiance(ctx, scene, s, view), split, "unsorted " + how + ", compaction " + toString(compaction));
  }
  for (KeyStrategy strategy : {KeyStrategy::Fixed, KeyStrategy::Average})
    for (Fusion fusion : {Fusion::None, Fusion::Gather, Fusion::Both})
      for (SortPolicy policy : policies) {
        Settings s = base;
        s.strategy = strategy;
        s.fusion = fusion;
        s.sortPolicy = policy;
        s.traceShade = traceShade;
        expectSameImage(renderRadiance(ctx, scene, s, view), split,
                        toString(strategy) + " " + how + " " + toString(fusion) + " " + toString(policy));
      }
}

TEST_F(TraceShadeRender, FusedRendersTheSplitImage) {
  expectTheSplitImage(ctx(), raylab::TraceShade::Fused, {SortPolicy::Always, SortPolicy::Auto});
}

// One frame of `s` (split) and of `s` with `traceShade`: the same rays per bounce, every bounce some. Returns the
// second frame's statistics.
FrameStats sameRaysAsSplit(const VulkanContext& ctx, const Scene& scene, const Viewpoint& view, Settings s,
                           TraceShade traceShade) {
  PathTracer split(ctx, scene, s, view);
  const FrameStats want = split.renderFrame();
  s.traceShade = traceShade;
  PathTracer other(ctx, scene, s, view);
  const FrameStats got = other.renderFrame();
  EXPECT_EQ(got.bounces.size(), want.bounces.size());
  for (size_t b = 0; b < std::min(want.bounces.size(), got.bounces.size()); ++b) {
    EXPECT_EQ(got.bounces[b].rays, want.bounces[b].rays) << toString(traceShade) << " bounce " << b;
    EXPECT_GT(want.bounces[b].rays, 0u) << "bounce " << b;
  }
  return got;
}

// The same rays per bounce (the fused kernel counts what the trace counted); every bounce of an unsorted frame
// is one dispatch, and a heatmap of bounce 1 keeps that bounce split.
TEST_F(TraceShadeRender, CountsTheSameRaysAndSplitsOnlyWhereNeeded) {
  Scene scene = makeTemple();
  const Viewpoint& view = *scene.findViewpoint("hall");
  Settings s = smallFrame(40, 24, 4);
  const FrameStats got = sameRaysAsSplit(ctx(), scene, view, s, raylab::TraceShade::Fused);
  s.traceShade = raylab::TraceShade::Fused;
  EXPECT_EQ(stageCount(got, "trace+shade"), 4);
  EXPECT_EQ(stageCount(got, "trace") + stageCount(got, "shade"), 0);
  s.heatmap = HeatmapView::TraversalSteps;
  s.heatmapBounce = 1;
  PathTracer withHeatmap(ctx(), scene, s, view);
  const FrameStats mixed = withHeatmap.renderFrame();
  EXPECT_EQ(stageCount(mixed, "trace+shade"), 3);
  EXPECT_EQ(stageCount(mixed, "trace"), 1);
  EXPECT_EQ(stageCount(mixed, "shade"), 1);
}

// Settings::traceShade loop: the bounces after the frame's last sort as one dispatch (shade.comp's bounce loop),
// under always and never (auto refuses it).
TEST_F(TraceShadeRender, LoopRendersTheSplitImage) {
  expectTheSplitImage(ctx(), raylab::TraceShade::Loop, {SortPolicy::Always, SortPolicy::Never});
}

// Where the loop starts: at bounce 0 of an unsorted frame or one whose policy sorts nothing (one dispatch for all
// bounces, the same rays counted per bounce), after a heatmap's bounce, and after the last sort.
TEST_F(TraceShadeRender, LoopStartsAfterTheLastBounceThatNeedsItsOwnStages) {
  Scene scene = makeTemple();
  const Viewpoint& view = *scene.findViewpoint("hall");
  Settings s = smallFrame(40, 24, 4);
  const FrameStats got = sameRaysAsSplit(ctx(), scene, view, s, raylab::TraceShade::Loop);
  s.traceShade = raylab::TraceShade::Loop;
  EXPECT_EQ(stageCount(got, "trace+shade"), 1);
  EXPECT_EQ(stageCount(got, "trace") + stageCount(got, "shade"), 0);

  Settings heat = s;
  heat.heatmap = HeatmapView::TraversalSteps;
  heat.heatmapBounce = 1;
  PathTracer withHeatmap(ctx(), scene, heat, view);
  const FrameStats mixed = withHeatmap.renderFrame();
  EXPECT_EQ(stageCount(mixed, "trace+shade"), 2);  // bounce 0 fused, bounce 1 split, bounces 2-3 looped
  EXPECT_EQ(stageCount(mixed, "trace"), 1);

  // A strategy under never sorts nothing: one loop. Under always (no fused gather) the last sort comes after
  // bounce 2, so bounces 0-2 fuse on their own and the loop is bounce 3 alone.
  Settings sorted = s;
  sorted.strategy = KeyStrategy::Fixed;
  sorted.fusion = Fusion::None;
  sorted.sortPolicy = SortPolicy::Never;
  PathTracer never(ctx(), scene, sorted, view);
  const FrameStats none = never.renderFrame();
  EXPECT_EQ(stageCount(none, "trace+shade"), 1);
  EXPECT_EQ(stageCount(none, "sort"), 0);
  sorted.sortPolicy = SortPolicy::Always;
  PathTracer always(ctx(), scene, sorted, view);
  const FrameStats every = always.renderFrame();
  EXPECT_EQ(stageCount(every, "trace+shade"), 4);
  EXPECT_EQ(stageCount(every, "sort"), 3);
  ASSERT_FALSE(every.stages.empty());
}

}  // namespace
}  // namespace raylab::test
