// The central invariant: sorting never changes the image. Each path's random stream depends on its id,
// not on its thread, and finished radiance is summed per pixel in sample order, so for every key
// strategy and sort the accumulated image must equal the unsorted one bit for bit (no tolerance).
#include <algorithm>
#include <cstring>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

#include "tests/gpu_test.h"
#include "tests/render_helpers.h"
#include "scenes/procedural.h"
#include "shaders/sort_types.h"

namespace raylab::test {

class SortInvariant : public GpuTest, public ::testing::WithParamInterface<SortAlgorithm> {};

TEST_P(SortInvariant, EveryStrategyRendersTheUnsortedImage) {
  Scene scene = makeTemple();
  const Viewpoint& view = *scene.findViewpoint("hall");
  Settings base = smallFrame(37, 19, 4);
  base.sppPerFrame = 2;
  base.frames = 2;  // the second frame uses what adaptive caches learned in the first
  std::vector<glm::vec3> unsorted = renderRadiance(ctx(), scene, base, view);
  ASSERT_GT(moments(unsorted).mean, 0.0);
  for (KeyStrategy strategy : allKeyStrategies()) {
    if (strategy == KeyStrategy::None) continue;
    Settings s = base;
    s.strategy = strategy;
    s.sort = GetParam();
    ASSERT_TRUE(s.sorts());
    expectSameImage(renderRadiance(ctx(), scene, s, view), unsorted, toString(strategy) + " with " + toString(GetParam()));
  }
}

// The same with the camera-clamped grid and an explicit grid, on the open viewpoint where many paths
// finish early (the live prefix shrinks fastest there).
TEST_P(SortInvariant, ClampedGridOnOpenView) {
  Scene scene = makeTemple();
  const Viewpoint& view = *scene.findViewpoint("openings");
  Settings base = smallFrame(33, 17, 5);
  std::vector<glm::vec3> unsorted = renderRadiance(ctx(), scene, base, view);
  for (KeyStrategy strategy : {KeyStrategy::Gaussian, KeyStrategy::TwoPoint, KeyStrategy::DeadLast}) {
    Settings s = base;
    s.strategy = strategy;
    s.sort = GetParam();
    s.clampToCamera = true;
    s.clampDistance = 20.0f;
    s.grid.automatic = false;
    s.grid.cells = {7, 3, 100};
    expectSameImage(renderRadiance(ctx(), scene, s, view), unsorted, toString(strategy));
  }
}

// Every sort policy: `never` sorts no bounce, `auto` sorts every bounce in its first frame, none in its
// second and then the bounces its measured costs pick (here lavapipe's, so whichever they are): each frame
// mixes sorted and unsorted bounces differently, and the image must still be the unsorted one.
TEST_P(SortInvariant, EverySortPolicyRendersTheUnsortedImage) {
  Scene scene = makeTemple();
  const Viewpoint& view = *scene.findViewpoint("hall");
  Settings base = smallFrame(37, 19, 5);
  base.frames = 5;
  std::vector<glm::vec3> unsorted = renderRadiance(ctx(), scene, base, view);
  for (SortPolicy policy : {SortPolicy::Never, SortPolicy::Auto, SortPolicy::Always}) {
    for (KeyStrategy strategy : {KeyStrategy::TwoPoint, KeyStrategy::Average}) {
      Settings s = base;
      s.strategy = strategy;
      s.sort = GetParam();
      s.sortPolicy = policy;
      expectSameImage(renderRadiance(ctx(), scene, s, view), unsorted, toString(strategy) + " with policy " + toString(policy));
    }
  }
}

// Ordering only the key's top bits (Settings::sortBits: 1, 8 and 9 bits, one and two radix passes for
// keys of 13 to 24 bits) is a coarser order, and sampled learning (Settings::learnEvery) other cache
// contents: never another image.
TEST_P(SortInvariant, SortingFewerKeyBitsRendersTheUnsortedImage) {
  Scene scene = makeTemple();
  const Viewpoint& view = *scene.findViewpoint("alley");
  Settings base = smallFrame(35, 18, 4);
  std::vector<glm::vec3> unsorted = renderRadiance(ctx(), scene, base, view);
  for (uint32_t sortBits : {1u, 8u, 9u}) {
    for (KeyStrategy strategy : {KeyStrategy::Fixed, KeyStrategy::TwoPoint, KeyStrategy::Ema}) {
      Settings s = base;
      s.strategy = strategy;
      s.sort = GetParam();
      s.sortBits = sortBits;
      s.learnEvery = sortBits;  // sampled learning changes what the cache holds, so the keys, never the image
      expectSameImage(renderRadiance(ctx(), scene, s, view), unsorted,
                      toString(strategy) + " sorting " + std::to_string(sortBits) + " key bits");
    }
  }
}

// A frame rendered in steps (PathTracer::recordSteps, several submissions, what the window does to stay
// live) is the whole-frame render bit for bit: uneven numbers of steps per submission (one, then several),
// over two frames (the second uses what the caches learned in the first), for the unsorted wavefront, every
// sort policy's sorted wavefront and the megakernel. Every step is recorded exactly once, each submission
// reports the GPU time of each step it recorded, and the rays and stage names of a frame in steps are those
// of the whole frame, so its statistics describe whole frames.
std::vector<glm::vec3> renderSteppedRadiance(const VulkanContext& ctx, const Scene& scene, const Settings& settings,
                                             const Viewpoint& view, std::vector<FrameStats>* frames,
                                             bool detailed = false) {
  const uint32_t counts[] = {1, 3, 2, 5, 1};
  PathTracer tracer(ctx, scene, settings, view);
  tracer.setDetailedStats(detailed);
  for (uint32_t f = 0; f < settings.frames; ++f) {
    size_t next = 0;
    const FrameStats* done = nullptr;
    uint32_t submissions = 0, steps = 0;
    const uint32_t frameSteps = uint32_t(tracer.pendingSteps().size());
    EXPECT_EQ(frameSteps, tracer.frameSteps()) << "a frame starts with all its steps pending";
    while (!done) {
      uint32_t recorded = 0;
      ctx.submitAndWait([&](VkCommandBuffer cmd) { recorded = tracer.recordSteps(cmd, counts[next++ % std::size(counts)]); });
      done = tracer.finishSteps(1.0);
      EXPECT_EQ(tracer.lastStepTimes().size(), recorded) << "a time for each step of the submission";
      steps += recorded;
      ++submissions;
    }
    EXPECT_GT(submissions, 2u);
    EXPECT_EQ(steps, frameSteps) << "every step once";
    EXPECT_EQ(done->wallMs, double(submissions)) << "wall time sums over the submissions";
    frames->push_back(*done);
  }
  return tracer.readRadiance();
}

std::vector<std::pair<std::string, int>> stageNames(const FrameStats& s) {
  std::vector<std::pair<std::string, int>> names;
  for (const StageTime& t : s.stages) names.emplace_back(t.stage, t.bounce);
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  return names;
}

TEST_P(SortInvariant, SteppedFramesRenderTheWholeFrameImage) {
  Scene scene = makeTemple();
  const Viewpoint& view = *scene.findViewpoint("hall");
  Settings base = smallFrame(37, 19, 4);
  base.sppPerFrame = 2;
  base.frames = 2;
  std::vector<Settings> cases;
  cases.push_back(base);
  for (SortPolicy policy : {SortPolicy::Always, SortPolicy::Auto}) {
    Settings s = base;
    s.strategy = KeyStrategy::Gaussian;
    s.sort = GetParam();
    s.sortPolicy = policy;
    cases.push_back(s);
  }
  Settings mega = base;
  mega.kernel = Kernel::Megakernel;
  cases.push_back(mega);
  for (const Settings& s : cases) {
    PathTracer whole(ctx(), scene, s, view);
    FrameStats wholeStats;
    for (uint32_t f = 0; f < s.frames; ++f) wholeStats = whole.renderFrame();
    std::vector<FrameStats> stepped;
    std::vector<glm::vec3> radiance = renderSteppedRadiance(ctx(), scene, s, view, &stepped);
    std::vector<glm::vec3> expected = whole.readRadiance();
    const std::string what = toString(s.kernel) + " " + toString(s.strategy) + " " + toString(s.sortPolicy);
    expectSameImage(radiance, expected, what + ", in steps,");
    ASSERT_EQ(stepped.size(), s.frames);
    EXPECT_EQ(stepped.back().raysTraced, wholeStats.raysTraced) << what;
    EXPECT_EQ(stepped.back().samplesPerPixel, wholeStats.samplesPerPixel) << what;
    if (s.sortPolicy != SortPolicy::Auto) {  // auto's second frame sorts where its (timed) costs say
      EXPECT_EQ(stageNames(stepped.back()), stageNames(wholeStats)) << what;
    }
    // The stage list has one entry per stage and bounce, as a whole frame's: a sort is one sort of the bounce.
    EXPECT_EQ(stageNames(stepped.back()).size(), stepped.back().stages.size()) << what;
  }
}

// Heatmaps in steps: every view, including those that depend on the whole frame's path order (sort-key
// ranks, warp efficiency), is the whole frame's heatmap image bit for bit, for the wavefront and the
// megakernel. Without compaction, whose packing order depends on timing (the warp efficiency reads the slot
// order). Fixed keys: a key that learns might learn in another order.
TEST_P(SortInvariant, SteppedHeatmapsAreTheWholeFrameHeatmap) {
  Scene scene = makeTemple();
  const Viewpoint& view = *scene.findViewpoint("hall");
  Settings base = smallFrame(37, 19, 3);
  base.strategy = KeyStrategy::Fixed;
  base.sort = GetParam();
  base.heatmapBounce = 1;
  base.compaction = Compaction::None;
  struct Case {
    HeatmapView heatmap;
    Kernel kernel;
    HeatmapKeyColour keyColour;
  };
  const Case cases[] = {{HeatmapView::TraversalSteps, Kernel::Wavefront, HeatmapKeyColour::Cell},
                        {HeatmapView::SortKey, Kernel::Wavefront, HeatmapKeyColour::Cell},
                        {HeatmapView::SortKey, Kernel::Wavefront, HeatmapKeyColour::Rank},
                        {HeatmapView::WarpEfficiency, Kernel::Wavefront, HeatmapKeyColour::Cell},
                        {HeatmapView::CellHit, Kernel::Wavefront, HeatmapKeyColour::Cell},
                        {HeatmapView::TraversalSteps, Kernel::Megakernel, HeatmapKeyColour::Cell}};
  for (const Case& c : cases) {
    Settings s = base;
    s.heatmap = c.heatmap;
    s.kernel = c.kernel;
    s.heatmapKeyColour = c.keyColour;
    const std::string what = toString(c.heatmap) + " " + toString(c.kernel) + " " + toString(c.keyColour);
    PathTracer whole(ctx(), scene, s, view);
    whole.renderFrame();
    PathTracer parts(ctx(), scene, s, view);
    uint32_t submissions = 0;
    for (const FrameStats* done = nullptr; !done; ++submissions) {
      ctx().submitAndWait([&](VkCommandBuffer cmd) { parts.recordSteps(cmd, 2); });
      done = parts.finishSteps(1.0);
    }
    EXPECT_GT(submissions, 2u) << what;
    EXPECT_EQ(parts.readImage(), whole.readImage()) << what << ": the heatmap in steps differs";
  }
}

// Detailed statistics of a frame in steps are those of the whole frame exactly: unsorted, the per-bounce warp
// efficiency and traversal steps (wavefront and megakernel); sorted with a key that learns nothing (fixed),
// every accuracy figure too (each sort sorts the whole bounce, as in a whole frame).
TEST_P(SortInvariant, SteppedFramesKeepDetailedStatistics) {
  Scene scene = makeTemple();
  const Viewpoint& view = *scene.findViewpoint("hall");
  Settings base = smallFrame(37, 19, 3);
  base.frames = 1;
  // Compaction packs paths in an order that depends on timing: per-slot figures are compared without it.
  base.compaction = Compaction::None;
  Settings sorted = base;
  sorted.strategy = KeyStrategy::Fixed;
  sorted.sort = GetParam();
  Settings mega = base;
  mega.kernel = Kernel::Megakernel;
  for (const Settings& s : {base, sorted, mega}) {
    PathTracer whole(ctx(), scene, s, view);
    whole.setDetailedStats(true);
    const FrameStats expected = whole.renderFrame();
    std::vector<FrameStats> stepped;
    renderSteppedRadiance(ctx(), scene, s, view, &stepped, true);
    const FrameStats& got = stepped.back();
    const std::string what = toString(s.kernel) + " " + toString(s.strategy);
    ASSERT_EQ(got.bounces.size(), expected.bounces.size()) << what;
    for (size_t b = 0; b < got.bounces.size(); ++b) {
      const BounceStats &g = got.bounces[b], &e = expected.bounces[b];
      EXPECT_EQ(g.rays, e.rays) << what << " bounce " << b;
      EXPECT_EQ(g.virtualWarpEfficiency, e.virtualWarpEfficiency) << what << " bounce " << b;
      EXPECT_EQ(g.meanTraversalSteps, e.meanTraversalSteps) << what << " bounce " << b;
      if (s.kernel == Kernel::Wavefront) {
        EXPECT_GT(e.virtualWarpEfficiency, 0.0) << what << " bounce " << b;
      }
      if (s.sorts() && b > 0) {
        EXPECT_GE(e.cellHitRate, 0.0) << what << " bounce " << b << ": measured";
      }
      EXPECT_EQ(g.cellHitRate, e.cellHitRate) << what << " bounce " << b;
      EXPECT_EQ(g.distinctKeys, e.distinctKeys) << what << " bounce " << b;
      EXPECT_EQ(g.predictionErrorMean, e.predictionErrorMean) << what << " bounce " << b;
      EXPECT_EQ(g.predictionErrorMedian, e.predictionErrorMedian) << what << " bounce " << b;
    }
  }
}

// The invariant on the trees the tests above do not walk: every BVH layout but the default one (with the
// default collapse), the default layout with every other collapse (each collapse is a scene of its own:
// its triangle order), and the default layout's tree optimized by reinsertion (Settings::bvhReinsert) and built
// from presplit references (Settings::bvhPresplit). Every key strategy (the oracle traces the same tree) with
// the radix sort, the bitonic and tile sorts and every sort policy with one strategy, and fused trace+shade render that tree's unsorted
// image bit for bit. One case per strategy, not per sort, so each tree adds about a third of the
// parameterised test above, not its double.
class SortInvariantLayouts : public GpuTest {};

struct Tree {
  BvhLayout layout;
  WideCollapse collapse;
  uint32_t reinsert;
  float presplit;
};

std::vector<Tree> treesBesidesTheDefault() {
  const Settings defaults;
  std::vector<Tree> trees;
  for (BvhLayout layout : allValues<BvhLayout>())
    if (layout != defaults.bvh) trees.push_back({layout, defaults.wideCollapse, defaults.bvhReinsert, defaults.bvhPresplit});
  for (WideCollapse collapse : allValues<WideCollapse>())
    if (collapse != defaults.wideCollapse)
      trees.push_back({defaults.bvh, collapse, defaults.bvhReinsert, defaults.bvhPresplit});
  trees.push_back({BvhLayout::Sbvh, defaults.wideCollapse, defaults.bvhReinsert == 0 ? 5u : 0u, defaults.bvhPresplit});
  trees.push_back({BvhLayout::Sbvh, defaults.wideCollapse, defaults.bvhReinsert, defaults.bvhPresplit == 0 ? 0.05f : 0.0f});
  return trees;
}

TEST_F(SortInvariantLayouts, EveryStrategySortAndPolicyRendersTheUnsortedImageOfEachTree) {
  const VulkanContext& context = ctx();
  Scene scene = makeTemple();
  const Viewpoint& view = *scene.findViewpoint("hall");
  for (const auto& [layout, collapse, reinsert, presplit] : treesBesidesTheDefault()) {
    Settings base = smallFrame(37, 19, 4);
    base.bvh = layout;
    base.wideCollapse = collapse;
    base.bvhReinsert = reinsert;
    base.bvhPresplit = presplit;
    base.sppPerFrame = 2;
    base.frames = 2;  // the second frame uses what adaptive caches learned in the first
    const std::vector<glm::vec3> unsorted = renderRadiance(context, scene, base, view);
    ASSERT_GT(moments(unsorted).mean, 0.0);
    std::vector<std::pair<std::string, Settings>> cases;
    for (KeyStrategy strategy : allKeyStrategies()) {
      if (strategy == KeyStrategy::None) continue;
      Settings s = base;
      s.strategy = strategy;
      s.sort = SortAlgorithm::Radix;
      cases.push_back({toString(strategy) + " radix", s});
    }
    for (SortAlgorithm sort : {SortAlgorithm::Bitonic, SortAlgorithm::Tile})
      for (SortPolicy policy : {SortPolicy::Always, SortPolicy::Never, SortPolicy::Auto}) {
        Settings s = base;
        s.strategy = KeyStrategy::TwoPoint;
        s.sort = sort;
        s.sortPolicy = policy;
        cases.push_back({"two-point " + toString(sort) + " " + toString(policy), s});
      }
    Settings fused = base;
    fused.traceShade = TraceShade::Fused;
    fused.strategy = KeyStrategy::Average;
    cases.push_back({"average, trace+shade fused", fused});
    // The bounce loop: after the last sort (always), and over the whole frame (never).
    for (SortPolicy policy : {SortPolicy::Always, SortPolicy::Never}) {
      Settings loop = base;
      loop.traceShade = TraceShade::Loop;
      loop.strategy = KeyStrategy::TwoPoint;
      loop.fusion = Fusion::None;
      loop.sortPolicy = policy;
      cases.push_back({"two-point " + toString(policy) + ", trace+shade loop", loop});
    }
    for (const auto& [what, s] : cases) {
      ASSERT_TRUE(s.sorts()) << what;
      expectSameImage(renderRadiance(context, scene, s, view), unsorted,
                      what + " on the " + toString(layout) + " BVH, " + toString(collapse) + " collapse, " +
                          std::to_string(reinsert) + " reinsertion passes, presplit " + std::to_string(presplit));
    }
  }
}

// The radix sorts have two forms: the single-dispatch small sort up to SORT_SMALL_MAX pairs (every frame above
// is that small) and their passes past it, three dispatches a pass (radix) or one (OneSweep, after one
// histogram; a dispatch a tile on lavapipe). All render the unsorted image, with the key's top bits only
// (Settings::sortBits) too; each frame's sort stage says which ran (one dispatch per sorted bounce, or more).
class SortInvariantSizes : public GpuTest {};

TEST_F(SortInvariantSizes, SmallSortAndRadixPassesRenderTheUnsortedImage) {
  Scene scene = makeTemple();
  const Viewpoint& view = *scene.findViewpoint("hall");
  for (const auto& [width, height] : {std::pair{37u, 19u}, std::pair{48u, 43u}}) {
    Settings base = smallFrame(width, height, 3);
    const bool small = base.width * base.height <= SORT_SMALL_MAX;
    ASSERT_EQ(small, width == 37u) << "the sizes no longer straddle the small sort's threshold";
    const std::vector<glm::vec3> unsorted = renderRadiance(ctx(), scene, base, view);
    for (SortAlgorithm sort : {SortAlgorithm::Radix, SortAlgorithm::OneSweep})
    for (KeyStrategy strategy : {KeyStrategy::Fixed, KeyStrategy::TwoPoint, KeyStrategy::Average})
      for (uint32_t sortBits : {0u, 8u})
      for (Fusion fusion : {Fusion::None, Fusion::Gather}) {
        if (sortBits != 0 && (strategy != KeyStrategy::TwoPoint || fusion != Fusion::None)) continue;
        Settings s = base;
        s.strategy = strategy;
        s.sort = sort;
        s.sortBits = sortBits;
        s.sortPolicy = SortPolicy::Always;
        s.fusion = fusion;
        const std::string what = toString(sort) + " " + toString(strategy) + " " + toString(fusion) + " sort bits " +
                                 std::to_string(sortBits) + " at " + std::to_string(width) + "x" + std::to_string(height);
        PathTracer tracer(ctx(), scene, s, view);
        uint32_t sortDispatches = 0;
        for (const StageCommands& c : tracer.renderFrame().stageCommands)
          if (c.stage == "sort") sortDispatches += c.counts.dispatches();
        if (small)
          EXPECT_EQ(sortDispatches, s.bounces - 1) << what << ": not the small sort";
        else if (sort == SortAlgorithm::Radix)
          EXPECT_GT(sortDispatches, 3 * (s.bounces - 1)) << what << ": not the radix passes";
        else
          EXPECT_GT(sortDispatches, s.bounces - 1) << what << ": not the OneSweep passes";
        expectSameImage(tracer.readRadiance(), unsorted, what);
      }
  }
}

INSTANTIATE_TEST_SUITE_P(Sorts, SortInvariant, ::testing::Values(SortAlgorithm::Radix, SortAlgorithm::Bitonic),
                         [](const auto& info) { return toString(info.param); });

}  // namespace raylab::test
