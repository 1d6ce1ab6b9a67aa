// Settings changed on a live tracer, as the window changes them: one SettingsChange decides what happens.
// Switching the key strategy or the sort mid-accumulation keeps accumulating (sorting never changes a
// sample), so the image equals one rendered unsorted throughout; a new bounce count or size restarts the
// image, which then equals a fresh tracer's.
#include <cstring>
#include <vector>

#include <gtest/gtest.h>

#include "scenes/procedural.h"
#include "tests/gpu_test.h"
#include "tests/render_helpers.h"

namespace raylab::test {
namespace {

class SettingsSwitch : public GpuTest {
 protected:
  Scene scene_ = makeTemple();
  Viewpoint view_ = *scene_.findViewpoint("hall");

  static Settings base() {
    Settings s;
    s.width = 37;  // not a multiple of any group or warp size
    s.height = 19;
    s.bounces = 4;
    return s;
  }
  static void expectSameImage(PathTracer& a, PathTracer& b, const char* what) {
    std::vector<glm::vec3> ra = a.readRadiance(), rb = b.readRadiance();
    ASSERT_EQ(ra.size(), rb.size()) << what;
    EXPECT_EQ(0, std::memcmp(ra.data(), rb.data(), ra.size() * sizeof(glm::vec3))) << what;
    EXPECT_EQ(a.readImage(), b.readImage()) << what;
  }
};

TEST_F(SettingsSwitch, StrategyAndSortMidAccumulationKeepTheUnsortedImage) {
  PathTracer reference(ctx(), scene_, base(), view_);
  for (int f = 0; f < 6; ++f) reference.renderFrame();

  PathTracer live(ctx(), scene_, base(), view_);
  live.renderFrame();
  live.renderFrame();
  Settings s = base();
  s.strategy = KeyStrategy::Ema;  // a length cache that learns from here on
  s.sort = SortAlgorithm::Radix;
  live.applySettings(s);
  EXPECT_EQ(live.accumulatedFrames(), 2u) << "a new strategy must not restart the image";
  live.renderFrame();
  live.renderFrame();
  s.strategy = KeyStrategy::TwoPoint;
  s.sort = SortAlgorithm::Bitonic;
  s.emaAlpha = 0.5f;
  live.applySettings(s);
  live.renderFrame();
  live.applySettings(base());  // and back to the plain wavefront
  const FrameStats& last = live.renderFrame();
  EXPECT_EQ(live.accumulatedFrames(), 6u);
  EXPECT_EQ(last.samplesPerPixel, 6u);
  expectSameImage(live, reference, "strategy switched mid-accumulation");
}

TEST_F(SettingsSwitch, BouncesAndSizeRestartLikeAFreshTracer) {
  Settings s = base();
  s.strategy = KeyStrategy::Gaussian;
  PathTracer live(ctx(), scene_, s, view_);
  live.renderFrame();
  live.renderFrame();

  s.bounces = 6;  // path state stays; the image starts again
  live.applySettings(s);
  EXPECT_EQ(live.accumulatedFrames(), 0u);
  live.renderFrame();
  live.renderFrame();
  PathTracer fresh(ctx(), scene_, s, view_);
  fresh.renderFrame();
  fresh.renderFrame();
  expectSameImage(live, fresh, "after a bounce change");
  EXPECT_EQ(live.renderFrame().bounces.size(), 6u);

  s.width = 24;  // new path buffers
  s.sppPerFrame = 2;
  live.applySettings(s);
  EXPECT_EQ(live.accumulatedFrames(), 0u);
  EXPECT_EQ(live.width(), 24u);
  live.renderFrame();
  PathTracer freshSize(ctx(), scene_, s, view_);
  freshSize.renderFrame();
  expectSameImage(live, freshSize, "after a size change");
}

// Another BVH layout restarts the image (it may break ties between equally near triangles otherwise), which
// then equals a fresh tracer's of that layout, sorted or not; and switching back does the same.
TEST_F(SettingsSwitch, BvhLayoutRestartsLikeAFreshTracer) {
  Settings s = base();
  s.strategy = KeyStrategy::TwoPoint;
  PathTracer live(ctx(), scene_, s, view_);
  live.renderFrame();
  live.renderFrame();
  const BvhLayout other = s.bvh == BvhLayout::Wide ? BvhLayout::Binary : BvhLayout::Wide;
  for (BvhLayout layout : {other, s.bvh}) {
    s.bvh = layout;
    live.applySettings(s);
    EXPECT_EQ(live.accumulatedFrames(), 0u) << toString(layout);
    live.renderFrame();
    live.renderFrame();
    Settings unsorted = base();
    unsorted.bvh = layout;
    PathTracer fresh(ctx(), scene_, unsorted, view_);
    fresh.renderFrame();
    fresh.renderFrame();
    expectSameImage(live, fresh, ("after switching to the " + toString(layout) + " BVH").c_str());
  }
}

TEST_F(SettingsSwitch, CameraMoveRestartsWithClampedAndUnclampedGrids) {
  Viewpoint moved = view_;
  moved.position += glm::vec3(0.5f, 0.0f, 0.25f);
  moved.target += glm::vec3(0.5f, 0.0f, 0.25f);
  for (bool clamp : {false, true}) {
    Settings s = base();
    s.strategy = KeyStrategy::Average;
    s.clampToCamera = clamp;
    s.clampDistance = 10.0f;
    PathTracer live(ctx(), scene_, s, view_);
    live.renderFrame();
    live.setCamera(moved);
    EXPECT_EQ(live.accumulatedFrames(), 0u);
    live.renderFrame();
    live.renderFrame();
    PathTracer fresh(ctx(), scene_, base(), moved);  // unsorted at the new camera
    fresh.renderFrame();
    fresh.renderFrame();
    expectSameImage(live, fresh, clamp ? "camera move, clamped grid" : "camera move, unclamped grid");
  }
}

}  // namespace
}  // namespace raylab::test
