// The central invariant: sorting never changes the image. Each path's random stream depends on its id,
// not on its thread, and finished radiance is summed per pixel in sample order, so for every key
// strategy and sort the accumulated image must equal the unsorted one bit for bit (no tolerance).
#include <cstring>

#include <gtest/gtest.h>

#include "tests/gpu_test.h"
#include "tests/render_helpers.h"
#include "scenes/procedural.h"

namespace raylab::test {

class SortInvariant : public GpuTest, public ::testing::WithParamInterface<SortAlgorithm> {};

TEST_P(SortInvariant, EveryStrategyRendersTheUnsortedImage) {
  Scene scene = makeTemple();
  const Viewpoint& view = *scene.findViewpoint("hall");
  Settings base;
  base.width = 37;  // not a multiple of any group or warp size
  base.height = 19;
  base.bounces = 4;
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
    std::vector<glm::vec3> sorted = renderRadiance(ctx(), scene, s, view);
    ASSERT_EQ(sorted.size(), unsorted.size());
    EXPECT_EQ(0, std::memcmp(sorted.data(), unsorted.data(), sorted.size() * sizeof(glm::vec3)))
        << toString(strategy) << " with " << toString(GetParam()) << " changed the image";
  }
}

// The same with the camera-clamped grid and an explicit grid, on the open viewpoint where many paths
// finish early (the live prefix shrinks fastest there).
TEST_P(SortInvariant, ClampedGridOnOpenView) {
  Scene scene = makeTemple();
  const Viewpoint& view = *scene.findViewpoint("openings");
  Settings base;
  base.width = 33;
  base.height = 17;
  base.bounces = 5;
  std::vector<glm::vec3> unsorted = renderRadiance(ctx(), scene, base, view);
  for (KeyStrategy strategy : {KeyStrategy::Gaussian, KeyStrategy::TwoPoint, KeyStrategy::DeadLast}) {
    Settings s = base;
    s.strategy = strategy;
    s.sort = GetParam();
    s.clampToCamera = true;
    s.clampDistance = 20.0f;
    s.grid.automatic = false;
    s.grid.cells = {7, 3, 100};
    std::vector<glm::vec3> sorted = renderRadiance(ctx(), scene, s, view);
    EXPECT_EQ(0, std::memcmp(sorted.data(), unsorted.data(), sorted.size() * sizeof(glm::vec3)))
        << toString(strategy) << " changed the image";
  }
}

// Every sort policy: `never` sorts no bounce, `auto` sorts every bounce in its first frame, none in its
// second and then the bounces its measured costs pick (here lavapipe's, so whichever they are): each frame
// mixes sorted and unsorted bounces differently, and the image must still be the unsorted one.
TEST_P(SortInvariant, EverySortPolicyRendersTheUnsortedImage) {
  Scene scene = makeTemple();
  const Viewpoint& view = *scene.findViewpoint("hall");
  Settings base;
  base.width = 37;
  base.height = 19;
  base.bounces = 5;
  base.frames = 5;
  std::vector<glm::vec3> unsorted = renderRadiance(ctx(), scene, base, view);
  for (SortPolicy policy : {SortPolicy::Never, SortPolicy::Auto, SortPolicy::Always}) {
    for (KeyStrategy strategy : {KeyStrategy::TwoPoint, KeyStrategy::Average}) {
      Settings s = base;
      s.strategy = strategy;
      s.sort = GetParam();
      s.sortPolicy = policy;
      std::vector<glm::vec3> sorted = renderRadiance(ctx(), scene, s, view);
      EXPECT_EQ(0, std::memcmp(sorted.data(), unsorted.data(), sorted.size() * sizeof(glm::vec3)))
          << toString(strategy) << " with policy " << toString(policy) << " changed the image";
    }
  }
}

// Ordering only the key's top bits (Settings::sortBits: 1, 8 and 9 bits, one and two radix passes for
// keys of 13 to 24 bits) is a coarser order, and sampled learning (Settings::learnEvery) other cache
// contents: never another image.
TEST_P(SortInvariant, SortingFewerKeyBitsRendersTheUnsortedImage) {
  Scene scene = makeTemple();
  const Viewpoint& view = *scene.findViewpoint("alley");
  Settings base;
  base.width = 35;
  base.height = 18;
  base.bounces = 4;
  std::vector<glm::vec3> unsorted = renderRadiance(ctx(), scene, base, view);
  for (uint32_t sortBits : {1u, 8u, 9u}) {
    for (KeyStrategy strategy : {KeyStrategy::Fixed, KeyStrategy::TwoPoint, KeyStrategy::Ema}) {
      Settings s = base;
      s.strategy = strategy;
      s.sort = GetParam();
      s.sortBits = sortBits;
      s.learnEvery = sortBits;  // sampled learning changes what the cache holds, so the keys, never the image
      std::vector<glm::vec3> sorted = renderRadiance(ctx(), scene, s, view);
      EXPECT_EQ(0, std::memcmp(sorted.data(), unsorted.data(), sorted.size() * sizeof(glm::vec3)))
          << toString(strategy) << " sorting " << sortBits << " key bits changed the image";
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Sorts, SortInvariant, ::testing::Values(SortAlgorithm::Radix, SortAlgorithm::Bitonic),
                         [](const auto& info) { return toString(info.param); });

}  // namespace raylab::test
