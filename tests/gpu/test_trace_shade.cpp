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
// learns from the sorted rays' hits, so those bounces stay split), each reorder and keys in shade, under the
// always and the auto policy, over two frames.
TEST_F(TraceShadeRender, FusedRendersTheSplitImage) {
  Scene scene = makeTemple();
  const Viewpoint& view = *scene.findViewpoint("openings");
  Settings base = smallFrame(33, 17, 5);
  base.frames = 2;
  const std::vector<glm::vec3> split = renderRadiance(ctx(), scene, base, view);
  ASSERT_GT(moments(split).mean, 0.0);
  for (Compaction compaction : {Compaction::None, Compaction::Shade}) {
    Settings s = base;
    s.compaction = compaction;
    s.traceShade = raylab::TraceShade::Fused;
    expectSameImage(renderRadiance(ctx(), scene, s, view), split, "unsorted, compaction " + toString(compaction));
  }
  for (KeyStrategy strategy : {KeyStrategy::Fixed, KeyStrategy::Average})
    for (Fusion fusion : {Fusion::None, Fusion::Gather, Fusion::Both})
      for (SortPolicy policy : {SortPolicy::Always, SortPolicy::Auto}) {
        Settings s = base;
        s.strategy = strategy;
        s.fusion = fusion;
        s.sortPolicy = policy;
        s.traceShade = raylab::TraceShade::Fused;
        expectSameImage(renderRadiance(ctx(), scene, s, view), split,
                        toString(strategy) + " fused " + toString(fusion) + " " + toString(policy));
      }
}

// The same rays per bounce (the fused kernel counts what the trace counted); every bounce of an unsorted frame
// is one dispatch, and a heatmap of bounce 1 keeps that bounce split.
TEST_F(TraceShadeRender, CountsTheSameRaysAndSplitsOnlyWhereNeeded) {
  Scene scene = makeTemple();
  const Viewpoint& view = *scene.findViewpoint("hall");
  Settings s = smallFrame(40, 24, 4);
  PathTracer split(ctx(), scene, s, view);
  const FrameStats want = split.renderFrame();
  s.traceShade = raylab::TraceShade::Fused;
  PathTracer fused(ctx(), scene, s, view);
  const FrameStats got = fused.renderFrame();
  ASSERT_EQ(got.bounces.size(), want.bounces.size());
  for (size_t b = 0; b < want.bounces.size(); ++b) EXPECT_EQ(got.bounces[b].rays, want.bounces[b].rays) << "bounce " << b;
  EXPECT_GT(want.bounces[1].rays, 0u);
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

}  // namespace
}  // namespace raylab::test
