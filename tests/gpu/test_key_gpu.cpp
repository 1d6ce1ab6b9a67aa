// GPU keys against their C++ twins: for every strategy and several grid settings, keys.comp must produce
// exactly the keys and predicted lengths of renderer/reorder/key_functions.cpp for the same paths (lavapipe, with
// validation on). The adaptive strategies are first taught some lengths so their cache lookups are real.
#include <algorithm>
#include <cmath>

#include "renderer/reorder/key_strategies.h"
#include "tests/exact_hit.h"
#include "tests/gpu_test.h"
#include "tests/test_key_support.h"

namespace raylab::test {
namespace {

class KeyGpu : public GpuTest {};

struct GridCase {
  const char* name;
  Settings settings;
  glm::vec3 camera;
};

std::vector<GridCase> gridCases() {
  std::vector<GridCase> cases;
  Settings s;
  cases.push_back({"auto", s, {5, 2, 3}});
  s.grid.automatic = false;
  s.grid.cells = {1, 1, 1};
  cases.push_back({"1x1x1", s, {5, 2, 3}});
  s.grid.cells = {1024, 1024, 1024};
  cases.push_back({"1024^3", s, {5, 2, 3}});
  s.grid.cells = {7, 3, 100};
  cases.push_back({"7x3x100", s, {5, 2, 3}});
  s = Settings{};
  s.clampToCamera = true;
  s.clampDistance = 2.5f;
  cases.push_back({"clamped", s, {3, 2, 4}});
  return cases;
}

// Teaches the cache a few bounces of hit distances (no-op for strategies without a cache).
void teach(const VulkanContext& ctx, KeyStage& stage, FakeFrame& frame, HostPaths paths, float scale) {
  for (uint32_t round = 0; round < 3; ++round) {
    setHits(paths, scale, 100 + round);
    frame.upload(paths);
    runLearn(ctx, stage, frame, static_cast<uint32_t>(paths.size()));
  }
}

TEST_F(KeyGpu, KeysEqualTwinForEveryStrategyAndGrid) {
  Scene scene = boxScene();
  const uint32_t n = 3001;  // not a multiple of the work-group size
  HostPaths paths = randomPaths(scene, n, 1);
  FakeFrame frame(ctx(), scene, n);
  KeyStage stage(ctx(), scene, {5, 2, 3}, Settings{}, n);
  for (const GridCase& c : gridCases()) {
    for (KeyStrategy strategy : allKeyStrategies()) {
      if (strategy == KeyStrategy::None) continue;
      SCOPED_TRACE(std::string(c.name) + " / " + toString(strategy));
      Settings s = c.settings;
      s.strategy = strategy;
      stage.configure(s, c.camera);
      teach(ctx(), stage, frame, paths, 8.0f);
      frame.upload(paths);
      KeyOutput out = runKeys(ctx(), stage, frame, n);
      std::vector<float> oracle = stage.downloadOracleLengths(n);
      EXPECT_EQ(compareWithTwin(stage, frame, paths, out, 1, oracle), 0u);
      if (strategyInfo(strategy).learnsLengths && stage.grid().gridBits() > 0) {
        // The learned lengths must actually be used for some paths (else this test proves little).
        uint32_t learned = 0;
        for (uint32_t i = 0; i < n; ++i)
          learned += out.predicted[i] > 0.0f && out.predicted[i] != stage.params().fixedLength;
        EXPECT_GT(learned, n / 10);
      }
    }
  }
}

// Slots past the live prefix of the last sort (GpuFrame::live) get the dead key and their own index whatever
// their state holds (stale rays of an earlier bounce may look alive), and their predicted length is not
// written; slots before it equal the twin as ever.
TEST_F(KeyGpu, SlotsPastTheLivePrefixGetTheDeadKey) {
  Scene scene = boxScene();
  const uint32_t n = 1000, live = 613;
  HostPaths paths = randomPaths(scene, n, 5);
  FakeFrame frame(ctx(), scene, n);
  Settings s;
  s.strategy = KeyStrategy::Fixed;
  KeyStage stage(ctx(), scene, {5, 2, 3}, s, n);
  frame.upload(paths);
  const KeyOutput all = runKeys(ctx(), stage, frame, n);
  frame.upload(paths, 3, 7, 0, live);
  const KeyOutput prefix = runKeys(ctx(), stage, frame, n);
  uint32_t liveBehind = 0;
  for (uint32_t i = 0; i < n; ++i) {
    EXPECT_EQ(prefix.values[i], i);
    if (i < live) {
      EXPECT_EQ(prefix.keys[i], all.keys[i]) << i;
      EXPECT_EQ(prefix.predicted[i], all.predicted[i]) << i;
    } else {
      EXPECT_EQ(prefix.keys[i], RL_DEAD_KEY) << i;
      EXPECT_EQ(prefix.predicted[i], -1.0f) << i;  // as uploaded: not written
      liveBehind += paths.alive[i];
    }
  }
  EXPECT_GT(liveBehind, (n - live) / 2);  // the paths behind the prefix were alive in their state
}

TEST_F(KeyGpu, NoneRecordsNothingAndKeyBitsMatchStrategy) {
  Scene scene = boxScene();
  const uint32_t n = 100;
  HostPaths paths = randomPaths(scene, n, 2);
  FakeFrame frame(ctx(), scene, n);
  frame.upload(paths);
  Settings s;
  s.grid.automatic = false;
  s.grid.cells = {7, 3, 100};  // 3 + 2 + 7 = 12 bits
  KeyStage stage(ctx(), scene, {5, 2, 3}, s, n);
  ctx().submitAndWait([&](VkCommandBuffer cmd) { frame.keys.recordFill(cmd, 0xABCDu); });
  KeyOutput out = runKeys(ctx(), stage, frame, n);
  EXPECT_EQ(stage.keyBits(), 0u);
  EXPECT_TRUE(std::all_of(out.keys.begin(), out.keys.end(), [](uint32_t k) { return k == 0xABCDu; }));
  const std::pair<KeyStrategy, uint32_t> widths[] = {
      {KeyStrategy::DeadLast, 1},  {KeyStrategy::Fixed, 13},           {KeyStrategy::Gaussian, 13},
      {KeyStrategy::Direction, 13}, {KeyStrategy::OriginDirection, 27}, {KeyStrategy::TwoPoint, 24}};  // two-point: 24 bits of code, top 23 kept
  for (auto [strategy, bits] : widths) {
    s.strategy = strategy;
    stage.configure(s, {5, 2, 3});
    EXPECT_EQ(stage.keyBits(), bits) << toString(strategy);
  }
}

TEST_F(KeyGpu, ConfigureAndResizeKeepOrResetTheCacheAsDocumented) {
  Scene scene = boxScene();
  const uint32_t n = 2000;
  HostPaths paths = randomPaths(scene, n, 4);
  FakeFrame frame(ctx(), scene, 2 * n);
  Settings s;
  s.strategy = KeyStrategy::Average;
  KeyStage stage(ctx(), scene, {5, 2, 3}, s, n);
  teach(ctx(), stage, frame, paths, 8.0f);
  double learned = stage.cacheOccupancy();
  EXPECT_GT(learned, 0.0);
  stage.resize(2 * n);  // more paths: what was learned stays
  EXPECT_EQ(stage.cacheOccupancy(), learned);
  s.emaAlpha = 0.5f;  // a parameter average does not use: no reset
  stage.configure(s, {5, 2, 3});
  EXPECT_EQ(stage.cacheOccupancy(), learned);
  HostPaths twice = randomPaths(scene, 2 * n, 5);
  frame.upload(twice);
  KeyOutput out = runKeys(ctx(), stage, frame, 2 * n);
  EXPECT_EQ(compareWithTwin(stage, frame, twice, out, 1), 0u);
  s.fixedFactor = 0.25f;  // changes the seed length: Settings::requiresCacheReset
  stage.configure(s, {5, 2, 3});
  EXPECT_EQ(stage.cacheOccupancy(), 0.0);
  teach(ctx(), stage, frame, paths, 8.0f);
  s.strategy = KeyStrategy::Fixed;  // no cache: its memory is given back
  stage.configure(s, {5, 2, 3});
  EXPECT_EQ(stage.cacheMemoryBytes(), 0u);
}

// Closest hit by brute force in double precision (the oracle's reference).
double closestHit(const Scene& scene, glm::dvec3 o, glm::dvec3 d) { return exactClosestHit(scene.triangles, o, d, 1e-12).t; }

TEST_F(KeyGpu, OracleTraceFindsTheTrueHit) {
  Scene scene = boxScene();
  const uint32_t n = 1000;
  HostPaths paths = randomPaths(scene, n, 3);
  FakeFrame frame(ctx(), scene, n);
  frame.upload(paths);
  Settings s;
  s.strategy = KeyStrategy::Oracle;
  KeyStage stage(ctx(), scene, {5, 2, 3}, s, n);
  KeyOutput out = runKeys(ctx(), stage, frame, n);
  std::vector<float> t = stage.downloadOracleLengths(n);
  uint32_t checked = 0, hits = 0, disagreements = 0;
  for (uint32_t i = 0; i < n; ++i) {
    glm::vec3 d(paths.direction[i]), o(paths.origin[i]);
    if (!paths.alive[i] || !validDirection(d) || !std::isfinite(o.x)) continue;
    double ref = closestHit(scene, o, d);
    ++checked;
    hits += ref > 0;
    // Origins on a triangle may or may not hit it at t ~ 0: only compare clear cases.
    if (ref > 1e-3 && std::abs(t[i] - ref) > 1e-3 * (1.0 + ref)) ++disagreements;
    if (t[i] > 1e-3f) {
      EXPECT_FLOAT_EQ(out.predicted[i], t[i]);
    }
  }
  EXPECT_GT(hits, checked / 2);
  EXPECT_LE(disagreements, checked / 200) << "of " << checked;
}

}  // namespace
}  // namespace raylab::test
