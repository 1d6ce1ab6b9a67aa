// Settings::compaction: a shade that packs the paths it keeps alive at the front of the other state set (one
// atomic per subgroup, so the slot order depends on timing) renders the image of the same tracer without it
// bit for bit, traces the same rays, and leaves no stale traversal steps behind the live prefix, also where
// sorted and compacted bounces alternate.
#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "tests/gpu_test.h"
#include "tests/render_helpers.h"
#include "scenes/procedural.h"

namespace raylab::test {
namespace {

class CompactionRender : public GpuTest {};

// On the open view, where most paths finish early, over two frames: the unsorted wavefront, and one strategy of
// each kind (grid key, length cache, oracle) under the always policy (every shade compacts before keys, sort
// and reorder) and the auto policy (frame 0 explores sorted, frame 1 unsorted), with every sort (the tile sort
// needs the compaction) and both reorders. Every strategy meets the compaction in the sort invariant tests,
// where it is the default.
TEST_F(CompactionRender, EveryVariantRendersTheUncompactedImage) {
  Scene scene = makeTemple();
  const Viewpoint& view = *scene.findViewpoint("openings");
  Settings base = smallFrame(33, 17, 5);
  base.frames = 2;
  base.compaction = raylab::Compaction::None;
  const std::vector<glm::vec3> unsorted = renderRadiance(ctx(), scene, base, view);
  ASSERT_GT(moments(unsorted).mean, 0.0);
  Settings packed = base;
  packed.compaction = raylab::Compaction::Shade;
  expectSameImage(renderRadiance(ctx(), scene, packed, view), unsorted, "unsorted, compacted,");
  for (KeyStrategy strategy : {KeyStrategy::Fixed, KeyStrategy::Average, KeyStrategy::Oracle}) {
    for (SortAlgorithm sort : {SortAlgorithm::Radix, SortAlgorithm::Bitonic, SortAlgorithm::Tile})
      for (SortPolicy policy : {SortPolicy::Always, SortPolicy::Auto}) {
        Settings s = packed;
        s.strategy = strategy;
        s.sort = sort;
        s.sortPolicy = policy;
        s.fusion = sort == SortAlgorithm::Bitonic ? Fusion::None : Fusion::Gather;
        expectSameImage(renderRadiance(ctx(), scene, s, view), unsorted,
                        toString(strategy) + " " + toString(sort) + " " + toString(policy) + " compacted");
      }
  }
}

// Per bounce: the same rays traced, the same traversal steps in total (slots behind the packed prefix hold
// no steps of rays traced bounces ago), and fuller warps: past the first bounce the live rays fill whole
// warps instead of sharing them with finished paths.
TEST_F(CompactionRender, TracesTheSameRaysInFullerWarps) {
  Scene scene = makeTemple();
  const Viewpoint& view = *scene.findViewpoint("openings");
  auto render = [&](raylab::Compaction compaction) {
    Settings s = smallFrame(64, 32, 4);
    s.compaction = compaction;
    PathTracer tracer(ctx(), scene, s, view);
    tracer.setDetailedStats(true);
    return tracer.renderFrame();
  };
  const FrameStats plain = render(raylab::Compaction::None);
  const FrameStats packed = render(raylab::Compaction::Shade);
  ASSERT_EQ(plain.bounces.size(), 4u);
  ASSERT_EQ(packed.bounces.size(), 4u);
  // The open view: fewer than half the paths are still live at bounce 1 (else nothing is compacted).
  ASSERT_LT(plain.bounces[1].rays * 2, plain.bounces[0].rays);
  for (size_t b = 0; b < 4; ++b) {
    EXPECT_EQ(packed.bounces[b].rays, plain.bounces[b].rays) << "bounce " << b;
    EXPECT_EQ(packed.bounces[b].meanTraversalSteps, plain.bounces[b].meanTraversalSteps) << "bounce " << b;
  }
  for (size_t b = 1; b < 4; ++b)
    EXPECT_GT(packed.bounces[b].virtualWarpEfficiency, plain.bounces[b].virtualWarpEfficiency) << "bounce " << b;
}

// Plans that mix sorted and compacted bounces (the auto policy fed a cost history in which only one sort
// pays): sorting after bounce 0 only (compactions follow the sort), and after bounce 1 only (a compaction
// comes first, and the keys, sort and reorder see its live prefix). The keys pass runs once, the image is
// the unsorted one, for every sort and both reorders.
TEST_F(CompactionRender, SortsBeforeAndAfterCompactions) {
  Scene scene = makeTemple();
  const Viewpoint& view = *scene.findViewpoint("openings");
  Settings s = smallFrame(33, 17, 4);
  s.compaction = raylab::Compaction::None;
  const std::vector<glm::vec3> unsorted = renderRadiance(ctx(), scene, s, view);
  s.strategy = KeyStrategy::Fixed;
  s.sortPolicy = SortPolicy::Auto;
  s.compaction = raylab::Compaction::Shade;
  const SortPlan all{{true, true, true, false}, {}}, none{{false, false, false, false}, {}};
  for (uint32_t paying : {0u, 1u}) {
    // Sorted frames: sorting after bounce `paying` makes the next bounce free and costs nothing; after any
    // other it saves nothing and costs 100 ms.
    std::vector<StageTime> sorted, plain{{"trace", int(paying) + 1, 10.0}};
    for (int b = 0; b < 3; ++b)
      if (uint32_t(b) != paying) sorted.push_back({"keys", b, 100.0});
    std::vector<bool> want(4, false);
    want[paying] = true;
    for (SortAlgorithm sort : {SortAlgorithm::Radix, SortAlgorithm::Bitonic})
      for (Fusion fusion : {Fusion::None, Fusion::Gather}) {
        s.sort = sort;
        s.fusion = fusion;
        const std::string what = "fixed " + toString(sort) + ", sorted after bounce " + std::to_string(paying) +
                                 " only, fused " + toString(fusion);
        PathTracer tracer(ctx(), scene, s, view);
        // Cold frames (not samples), then sorted and unsorted alternately until each has its samples.
        const uint32_t history = SortPolicyModel::kColdFrames + 2 * SortPolicyModel::kMinSamples;
        for (uint32_t f = 0; f < history; ++f) tracer.sortPolicy().record(f % 2 == 0 ? all : none, f % 2 == 0 ? sorted : plain);
        const FrameStats stats = tracer.renderFrame();
        ASSERT_EQ(tracer.sortPlan().sortAfter, want) << what;
        const auto keysPasses = std::count_if(stats.stages.begin(), stats.stages.end(),
                                              [](const StageTime& t) { return t.stage == "keys"; });
        EXPECT_EQ(keysPasses, 1) << what;
        expectSameImage(tracer.readRadiance(), unsorted, what);
      }
  }
}

// The window renders a frame in steps over several submissions: the compactions carry over between them.
TEST_F(CompactionRender, CompactedFramesInStepsRenderTheWholeFrameImage) {
  Scene scene = makeTemple();
  const Viewpoint& view = *scene.findViewpoint("openings");
  Settings s = smallFrame(37, 19, 4);
  s.compaction = raylab::Compaction::Shade;
  const std::vector<glm::vec3> whole = renderRadiance(ctx(), scene, s, view);
  uint32_t submissions = 0;
  const std::vector<glm::vec3> stepped = renderRadianceInSteps(ctx(), scene, s, view, submissions);
  EXPECT_GT(submissions, 2u);
  expectSameImage(stepped, whole, "compacted, in steps,");
}

}  // namespace
}  // namespace raylab::test
