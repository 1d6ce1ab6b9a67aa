// Stability where the methods fail: flat scenes, the camera outside the clamped scene, clamp distances 0
// and huge, grids 1x1x1 and the largest allowed, NaN and zero directions, a Gaussian cell fed a million
// nearly equal large lengths, reset thresholds 0 and infinity. In each, for every strategy: no NaN or
// infinite length, every key within the key width (or the dead key), GPU equal to the C++ twin, and no
// validation error (the fixture checks that).
#include <cmath>
#include <limits>
#include <random>

#include "tests/gpu_test.h"
#include "tests/test_key_support.h"

namespace raylab::test {
namespace {

class KeyStability : public GpuTest {
 protected:
  void checkAllStrategies(const Scene& scene, Settings s, glm::vec3 camera, const HostPaths& paths) {
    const uint32_t n = static_cast<uint32_t>(paths.size());
    FakeFrame frame(ctx(), scene, n);
    KeyStage stage(ctx(), scene, camera, s, n);
    float scale = std::max(stage.grid().sceneDiagonal, 1e-3f);
    for (KeyStrategy strategy : allKeyStrategies()) {
      if (strategy == KeyStrategy::None) continue;
      SCOPED_TRACE(toString(strategy));
      s.strategy = strategy;
      stage.configure(s, camera);
      HostPaths learn = paths;
      for (uint32_t round = 0; round < 3; ++round) {
        setHits(learn, scale, round);
        learn.hitT[0] = std::numeric_limits<float>::quiet_NaN();  // a broken trace must not poison a cell
        learn.hitT[1] = std::numeric_limits<float>::infinity();
        frame.upload(learn);
        runLearn(ctx(), stage, frame, n);
      }
      for (const gpu::GpuCacheEntry& e : stage.downloadCache().entries) {
        ASSERT_TRUE(std::isfinite(e.mean) && std::isfinite(e.m2) && std::isfinite(e.sigma));
        ASSERT_GE(e.m2, 0.0f);
      }
      frame.upload(paths);
      KeyOutput out = runKeys(ctx(), stage, frame, n);
      EXPECT_EQ(compareWithTwin(stage, frame, paths, out, 1, stage.downloadOracleLengths(n)), 0u);
    }
  }
};

TEST_F(KeyStability, SceneFlatOnOneAxis) {
  Scene flat = boxScene({0, 0, 0}, {10, 4, 6}, true);
  checkAllStrategies(flat, Settings{}, {5, 1, 3}, randomPaths(flat, 2000, 1));
}

TEST_F(KeyStability, CameraOutsideTheSceneWithClamping) {
  Scene scene = boxScene();
  Settings s;
  s.clampToCamera = true;
  s.clampDistance = 3.0f;
  checkAllStrategies(scene, s, {40, 2, 3}, randomPaths(scene, 2000, 2));      // misses the scene on x
  checkAllStrategies(scene, s, {-50, -50, -50}, randomPaths(scene, 2000, 3));  // on every axis
}

TEST_F(KeyStability, ClampDistanceZeroAndHuge) {
  Scene scene = boxScene();
  Settings s;
  s.clampToCamera = true;
  s.clampDistance = 0.0f;
  checkAllStrategies(scene, s, {5, 2, 3}, randomPaths(scene, 2000, 4));
  s.clampDistance = SettingLimits::kMaxClampDistance;
  checkAllStrategies(scene, s, {5, 2, 3}, randomPaths(scene, 2000, 5));
}

TEST_F(KeyStability, GridOneCellAndLargestAllowed) {
  Scene scene = boxScene();
  Settings s;
  s.grid.automatic = false;
  s.grid.cells = {1, 1, 1};
  checkAllStrategies(scene, s, {5, 2, 3}, randomPaths(scene, 2000, 6));
  s.grid.cells = glm::uvec3(SettingLimits::kMaxGridCellsPerAxis);
  checkAllStrategies(scene, s, {5, 2, 3}, randomPaths(scene, 2000, 7));
}

TEST_F(KeyStability, NanAndZeroDirections) {
  Scene scene = boxScene();
  HostPaths paths = randomPaths(scene, 1000, 8, false);
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  const glm::vec3 bad[] = {{nan, nan, nan}, {0, 0, 0}, {-0.0f, 0, 0}, {inf, 1, 0}, {1e-38f, 0, 0}, {nan, 1, 0}};
  for (size_t i = 0; i < paths.size(); ++i) paths.direction[i] = glm::vec4(bad[i % 6], 0.0f);
  checkAllStrategies(scene, Settings{}, {5, 2, 3}, paths);
}

TEST_F(KeyStability, GaussianMillionNearlyEqualLargeLengths) {
  Scene scene = boxScene({0, 0, 0}, {2e4f, 2e4f, 2e4f});
  const uint32_t n = 1u << 16, rounds = 16;  // 2^20 samples into one cell
  HostPaths paths;
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (uint32_t i = 0; i < n; ++i) {
    paths.origin.push_back({100 + 10 * u(rng), 0, 100 + 10 * u(rng), 0});  // one floor cell
    paths.direction.push_back(glm::vec4(glm::normalize(glm::vec3(0.2f + u(rng), 1, 0.2f + u(rng))), 0));
    paths.pathId.push_back(i);
    paths.alive.push_back(1);
    paths.hitT.push_back(1e4f);
  }
  FakeFrame frame(ctx(), scene, n);
  Settings s;
  s.strategy = KeyStrategy::Gaussian;
  KeyStage stage(ctx(), scene, {1e4f, 1e4f, 1e4f}, s, n);
  for (uint32_t round = 0; round < rounds; ++round) {
    for (uint32_t i = 0; i < n; ++i) paths.hitT[i] = 1e4f + 1e-2f * u(rng);
    frame.upload(paths);
    runLearn(ctx(), stage, frame, n);
  }
  LengthCache::Contents c = stage.downloadCache();
  uint64_t total = 0;
  for (const gpu::GpuCacheEntry& e : c.entries) {
    ASSERT_TRUE(std::isfinite(e.mean) && std::isfinite(e.m2) && std::isfinite(e.sigma));
    ASSERT_GE(e.m2, 0.0f);
    total += e.count;
    if (e.count == 0) continue;
    EXPECT_NEAR(e.mean, 1e4f + 5e-3f, 0.05f);
    EXPECT_LT(e.sigma, 0.05f);
  }
  EXPECT_EQ(total + stage.cacheOutliersRejected(), uint64_t(n) * rounds);
  KeyOutput out = runKeys(ctx(), stage, frame, n);
  for (uint32_t i = 0; i < n; ++i) ASSERT_NEAR(out.predicted[i], 1e4f, 1.0f) << i;
  EXPECT_EQ(compareWithTwin(stage, frame, paths, out, 1), 0u);
}

TEST_F(KeyStability, GaussianResetThresholdZeroAndInfinity) {
  Scene scene = boxScene();
  const uint32_t n = 3000;
  HostPaths paths = randomPaths(scene, n, 10);
  for (float threshold : {0.0f, std::numeric_limits<float>::infinity()}) {
    SCOPED_TRACE(threshold);
    Settings s;
    s.strategy = KeyStrategy::Gaussian;
    s.gaussReset = threshold;
    FakeFrame frame(ctx(), scene, n);
    KeyStage stage(ctx(), scene, {5, 2, 3}, s, n);
    uint32_t maxCount = 0;
    for (uint32_t round = 0; round < 4; ++round) {
      setHits(paths, 10.0f, 20 + round);
      frame.upload(paths);
      runLearn(ctx(), stage, frame, n);
    }
    for (const gpu::GpuCacheEntry& e : stage.downloadCache().entries) {
      ASSERT_TRUE(std::isfinite(e.mean) && std::isfinite(e.m2) && std::isfinite(e.sigma));
      ASSERT_GE(e.m2, 0.0f);
      if (threshold == 0.0f) {
        EXPECT_EQ(e.sigma, 0.0f);  // every cell with any spread was reset
      }
      maxCount = std::max(maxCount, e.count);
    }
    if (threshold > 0.0f) {
      EXPECT_GT(maxCount, 20u);  // never reset: cells keep growing over the bounces
    }
    frame.upload(paths);
    KeyOutput out = runKeys(ctx(), stage, frame, n);
    EXPECT_EQ(compareWithTwin(stage, frame, paths, out, 1), 0u);
  }
}

}  // namespace
}  // namespace raylab::test
