// Settings::fusion: the keys made in shade and the reorder done by the next trace are the separate passes'
// keys and permutation, not merely an image that happens to match. Each fused variant renders the unsorted
// image bit for bit (the invariant); the keys are checked through what depends on them: the sort-key
// heatmaps (key per pixel, rank per pixel), the per-bounce statistics the detailed readbacks compute from the
// keys, predicted lengths and hits (distinct keys, prediction error, cell hits, warp efficiency), and what
// the length caches learn from the predictions over two frames.
#include <algorithm>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

#include "tests/gpu_test.h"
#include "tests/render_helpers.h"
#include "scenes/procedural.h"

namespace raylab::test {
namespace {

constexpr Fusion kFused[] = {Fusion::Keys, Fusion::Gather, Fusion::Both};

bool hasStage(const FrameStats& s, const std::string& stage) {
  return std::any_of(s.stages.begin(), s.stages.end(), [&](const StageTime& t) { return t.stage == stage; });
}

class FusedStages : public GpuTest, public ::testing::WithParamInterface<SortAlgorithm> {};

// On the open view, where the live prefix shrinks fastest (the gathering trace finds it), over two frames
// (the caches use what they learned): both fusions for every strategy (the oracle keeps its keys pass), each
// fusion alone for one strategy of each kind, and the auto policy (a frame that sorts some bounces only).
TEST_P(FusedStages, EveryFusionRendersTheUnsortedImage) {
  Scene scene = makeTemple();
  const Viewpoint& view = *scene.findViewpoint("openings");
  Settings base = smallFrame(33, 17, 5);
  base.frames = 2;
  const std::vector<glm::vec3> unsorted = renderRadiance(ctx(), scene, base, view);
  ASSERT_GT(moments(unsorted).mean, 0.0);
  const KeyStrategy oneOfEachKind[] = {KeyStrategy::Fixed, KeyStrategy::TwoPoint, KeyStrategy::Average, KeyStrategy::Oracle};
  for (Fusion fusion : kFused) {
    for (KeyStrategy strategy : allKeyStrategies()) {
      if (strategy == KeyStrategy::None) continue;
      if (fusion != Fusion::Both && std::find(std::begin(oneOfEachKind), std::end(oneOfEachKind), strategy) == std::end(oneOfEachKind))
        continue;
      for (SortPolicy policy : {SortPolicy::Always, SortPolicy::Auto}) {
        if (policy == SortPolicy::Auto && (fusion != Fusion::Both || (strategy != KeyStrategy::TwoPoint && strategy != KeyStrategy::Average)))
          continue;
        Settings s = base;
        s.strategy = strategy;
        s.sort = GetParam();
        s.sortPolicy = policy;
        s.fusion = fusion;
        s.sortBits = strategy == KeyStrategy::Fixed ? 8 : 0;
        expectSameImage(renderRadiance(ctx(), scene, s, view), unsorted,
                        toString(strategy) + " " + toString(policy) + " fused " + toString(fusion));
      }
    }
  }
}

// Detailed statistics per bounce over two frames equal the separate passes' exactly, and the stages say what
// ran: no keys pass where shade made them (but the oracle's), no reorder pass where the trace gathered.
TEST_P(FusedStages, FusedStagesKeepKeysAndStatistics) {
  Scene scene = makeTemple();
  const Viewpoint& view = *scene.findViewpoint("hall");
  for (KeyStrategy strategy : {KeyStrategy::Fixed, KeyStrategy::TwoPoint, KeyStrategy::Average, KeyStrategy::Oracle}) {
    Settings base = smallFrame(37, 19, 4);
    base.strategy = strategy;
    base.sort = GetParam();
    // Compaction packs paths in an order that depends on timing (and bitonic is not stable): per-slot
    // figures are compared without it.
    base.compaction = Compaction::None;
    auto render = [&](Fusion fusion) {
      Settings s = base;
      s.fusion = fusion;
      PathTracer tracer(ctx(), scene, s, view);
      tracer.setDetailedStats(true);
      tracer.renderFrame();
      return tracer.renderFrame();
    };
    const FrameStats separate = render(Fusion::None);
    ASSERT_TRUE(hasStage(separate, "keys") && hasStage(separate, "reorder"));
    for (Fusion fusion : kFused) {
      const FrameStats fused = render(fusion);
      const std::string what = toString(strategy) + " fused " + toString(fusion);
      const bool keysFused = fusion != Fusion::Gather && strategy != KeyStrategy::Oracle;
      EXPECT_EQ(hasStage(fused, "keys"), !keysFused) << what;
      EXPECT_EQ(hasStage(fused, "reorder"), fusion == Fusion::Keys) << what;
      ASSERT_EQ(fused.bounces.size(), separate.bounces.size()) << what;
      for (size_t b = 0; b < fused.bounces.size(); ++b) {
        const BounceStats &g = fused.bounces[b], &e = separate.bounces[b];
        EXPECT_EQ(g.rays, e.rays) << what << " bounce " << b;
        EXPECT_EQ(g.distinctKeys, e.distinctKeys) << what << " bounce " << b;
        EXPECT_EQ(g.cellHitRate, e.cellHitRate) << what << " bounce " << b;
        EXPECT_EQ(g.predictionErrorMean, e.predictionErrorMean) << what << " bounce " << b;
        EXPECT_EQ(g.virtualWarpEfficiency, e.virtualWarpEfficiency) << what << " bounce " << b;
        EXPECT_EQ(g.meanTraversalSteps, e.meanTraversalSteps) << what << " bounce " << b;
      }
      EXPECT_GT(separate.bounces[2].distinctKeys, 0) << what << ": keys were read back";
    }
  }
}

// The sort-key heatmap shows the keys made for the next bounce's rays in their pixels (cell colouring) and
// where the sort put them (rank colouring): the fused frames' heatmaps are the separate passes' bit for bit.
TEST_P(FusedStages, SortKeyHeatmapsAreTheSeparatePassesHeatmaps) {
  Scene scene = makeTemple();
  const Viewpoint& view = *scene.findViewpoint("alley");
  for (HeatmapKeyColour colour : {HeatmapKeyColour::Cell, HeatmapKeyColour::Rank}) {
    Settings base = smallFrame(35, 18, 3);
    base.strategy = KeyStrategy::TwoPoint;
    base.sort = GetParam();
    // Compaction packs paths in an order that depends on timing (and bitonic is not stable): per-slot
    // figures are compared without it.
    base.compaction = Compaction::None;
    base.heatmap = HeatmapView::SortKey;
    base.heatmapKeyColour = colour;
    base.heatmapBounce = 2;
    auto heatmap = [&](Fusion fusion) {
      Settings s = base;
      s.fusion = fusion;
      PathTracer tracer(ctx(), scene, s, view);
      tracer.renderFrame();
      return tracer.readImage();
    };
    const std::vector<uint32_t> separate = heatmap(Fusion::None);
    ASSERT_GT(std::count_if(separate.begin(), separate.end(), [&](uint32_t p) { return p != separate[0]; }), 10);
    for (Fusion fusion : kFused)
      EXPECT_EQ(heatmap(fusion), separate) << toString(colour) << " fused " << toString(fusion);
  }
}

// The window renders a frame in steps over several submissions: the fused stages' state carries over.
TEST_P(FusedStages, FusedFramesInStepsRenderTheWholeFrameImage) {
  Scene scene = makeTemple();
  const Viewpoint& view = *scene.findViewpoint("hall");
  Settings s = smallFrame(37, 19, 4);
  s.strategy = KeyStrategy::Average;
  s.sort = GetParam();
  s.fusion = Fusion::Both;
  const std::vector<glm::vec3> whole = renderRadiance(ctx(), scene, s, view);
  uint32_t submissions = 0;
  const std::vector<glm::vec3> stepped = renderRadianceInSteps(ctx(), scene, s, view, submissions);
  EXPECT_GT(submissions, 2u);
  expectSameImage(stepped, whole, "average fused both, in steps,");
}

INSTANTIATE_TEST_SUITE_P(Sorts, FusedStages, ::testing::Values(SortAlgorithm::Radix, SortAlgorithm::Bitonic),
                         [](const auto& info) { return toString(info.param); });

}  // namespace
}  // namespace raylab::test
