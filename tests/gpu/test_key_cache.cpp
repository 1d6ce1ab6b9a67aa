// The length cache on the GPU: its learning matches a double-precision reference for average, ema and
// gaussian, is deterministic, skips misses and dead paths, rejects outliers and resets high-variance cells,
// and counts its resets in the frame's counters as the reference does.
// (Its host-side layout is tested in tests/cpu/test_length_cache_layout.cpp.)
#include <cmath>
#include <cstring>
#include <map>
#include <random>

#include "tests/gpu_test.h"
#include "tests/test_key_support.h"

namespace raylab::test {
namespace {

class LengthCacheGpu : public GpuTest {};

// Three groups of paths, each sharing one (cell, octant) entry, fed four bounces of known lengths.
struct Groups {
  HostPaths paths;
  std::vector<int> group;  // per path
};

Groups threeGroups(uint32_t perGroup) {
  Groups g;
  const glm::vec3 origins[3] = {{1, 0.0f, 1}, {9, 2, 0.0f}, {5, 4, 3}};  // on the floor, a wall, the ceiling
  const glm::vec3 dirs[3] = {{0.3f, 0.9f, 0.3f}, {-0.5f, 0.5f, 0.7f}, {0.2f, -0.9f, -0.4f}};
  for (int k = 0; k < 3; ++k)
    for (uint32_t i = 0; i < perGroup; ++i) {
      g.paths.origin.push_back(glm::vec4(origins[k], 0));
      g.paths.direction.push_back(glm::vec4(glm::normalize(dirs[k]), 0));
      g.paths.pathId.push_back(k * perGroup + i);
      g.paths.alive.push_back(1);
      g.paths.hitT.push_back(1.0f);
      g.group.push_back(k);
    }
  return g;
}

// One entry in double precision, updated as key_merge.comp updates it.
struct Reference {
  double count = 0, mean = 0, m2 = 0;

  // Folds in a batch of n samples (mean mb, sum of squared deviations m2b); true when the entry is reset
  // (the Gaussian reset: the non-finite restart the shader also counts never happens here).
  bool merge(double n, double mb, double m2b, KeyStrategy strategy, double emaAlpha, double gaussReset) {
    auto variance = [](double c, double m) { return c >= 2 ? m / (c - 1) : 0.0; };
    Reference next{n, mb, m2b};
    if (count > 0 && strategy == KeyStrategy::Ema) {
      next = {count + n, mean + (1.0 - std::pow(1.0 - emaAlpha, n)) * (mb - mean), 0.0};
    } else if (count > 0) {
      double nn = count + n, d = mb - mean;
      next = {nn, mean + d * n / nn, m2 + m2b + d * d * count * n / nn};
    }
    const bool reset = strategy == KeyStrategy::Gaussian && variance(next.count, next.m2) > gaussReset;
    if (reset) next = variance(n, m2b) <= gaussReset ? Reference{n, mb, m2b} : Reference{};
    *this = next;
    return reset;
  }
};

// The hit length of a path of group k (0..2) in learning round r, from a uniform u in [0, 1).
using GroupLengths = float (*)(int k, int round, float u);
float driftingLengths(int k, int round, float u) { return 1.0f + 2.0f * k + (0.5f + round * 0.1f) * u; }

// Four rounds of learning (bounce 1) by three groups of 300 paths, each group one entry, checked entry by entry
// and round by round (the resets key_merge.comp counted in the frame's counters) against the reference.
// learnEvery > 1: only slots i with (i + frameIndex + bounce) % learnEvery == 0 learn (Settings::learnEvery),
// the frame index moving each round so the sampled slots change; the reference takes the same slots.
// Returns the resets counted over the rounds.
uint32_t learnAndCompare(const VulkanContext& ctx, KeyStrategy strategy, uint32_t learnEvery = 1,
                         GroupLengths lengths = driftingLengths, float gaussReset = INFINITY) {
  Scene scene = boxScene();
  const uint32_t per = 300;
  Groups g = threeGroups(per);
  const uint32_t n = static_cast<uint32_t>(g.paths.size());
  FakeFrame frame(ctx, scene, n);
  Settings s;
  s.strategy = strategy;
  s.gaussOutlier = 100.0f;  // no outliers: the plain statistics
  s.gaussReset = gaussReset;
  s.emaAlpha = 0.01f;
  s.learnEvery = learnEvery;
  KeyStage stage(ctx, scene, {5, 2, 3}, s, n);
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  Reference ref[3];
  uint32_t resets = 0;
  for (int round = 0; round < 4; ++round) {
    double bsum[3] = {}, bsq[3] = {}, bn[3] = {};
    const uint32_t frameIndex = 3 + round, bounce = 1;
    for (uint32_t i = 0; i < n; ++i) {
      float t = lengths(g.group[i], round, u(rng));
      g.paths.hitT[i] = t;
      if ((i + frameIndex + bounce) % learnEvery != 0) continue;
      bsum[g.group[i]] += t, bsq[g.group[i]] += double(t) * t, bn[g.group[i]] += 1;
    }
    uint32_t refResets = 0;
    for (int k = 0; k < 3; ++k) {
      double mb = bsum[k] / bn[k], m2b = bsq[k] - bsum[k] * mb;
      refResets += ref[k].merge(bn[k], mb, m2b, strategy, s.emaAlpha, s.gaussReset) ? 1u : 0u;
    }
    frame.upload(g.paths, frameIndex);
    frame.clearCounters();
    runLearn(ctx, stage, frame, n, bounce);
    const uint32_t counted = frame.counter(bounce, RL_COUNTER_CACHE_RESETS);
    EXPECT_EQ(counted, refResets) << toString(strategy) << " round " << round;
    resets += counted;
  }
  LengthCache::Contents c = stage.downloadCache();
  KeyEnv env;
  env.slotKeys = c.slotKeys;
  env.slotValues = c.slotValues;
  int holding = 0;
  for (int k = 0; k < 3; ++k) {
    uint32_t i = k * per;
    glm::vec3 o(g.paths.origin[i]), d(g.paths.direction[i]);
    int32_t e = cacheEntry(stage.params().cache, env, stage.params().grid, stage.grid().cell(o), d);
    EXPECT_GE(e, 0) << "group " << k;
    if (e < 0) return resets;
    const gpu::GpuCacheEntry& entry = c.entries[e];
    holding += ref[k].count > 0 ? 1 : 0;
    EXPECT_EQ(entry.count, uint32_t(ref[k].count)) << toString(strategy) << " group " << k;
    EXPECT_NEAR(entry.mean, ref[k].mean, 1e-5 * ref[k].mean) << toString(strategy) << " group " << k;
    if (strategy == KeyStrategy::Gaussian && ref[k].count >= 2) {
      EXPECT_NEAR(entry.m2, ref[k].m2, 1e-3 * ref[k].m2);
      EXPECT_NEAR(entry.sigma, std::sqrt(ref[k].m2 / (ref[k].count - 1)), 1e-3);
    }
  }
  // The groups' entries (1 octant each of the 8 x occupied entries) that hold samples.
  EXPECT_NEAR(stage.cacheOccupancy(), double(holding) / c.entries.size(), 1e-12);
  EXPECT_GT(stage.cacheMemoryBytes(), c.entries.size() * 36);
  return resets;
}

TEST_F(LengthCacheGpu, AverageMatchesReference) { EXPECT_EQ(learnAndCompare(ctx(), KeyStrategy::Average), 0u); }
TEST_F(LengthCacheGpu, EmaMatchesReference) { EXPECT_EQ(learnAndCompare(ctx(), KeyStrategy::Ema), 0u); }
TEST_F(LengthCacheGpu, GaussianMatchesReference) { EXPECT_EQ(learnAndCompare(ctx(), KeyStrategy::Gaussian), 0u); }
TEST_F(LengthCacheGpu, SampledAverageMatchesReference) { learnAndCompare(ctx(), KeyStrategy::Average, 3); }
TEST_F(LengthCacheGpu, SampledGaussianMatchesReference) { learnAndCompare(ctx(), KeyStrategy::Gaussian, 7); }

// Variances far from a reset threshold of 0.5 (so float and double agree on every reset): group 0 stays
// tight at 2 (never resets); group 1 is tight but jumps 2 -> 5 -> 5 -> 3 (its past dropped, the batch kept, in
// rounds 1 and 3: merged variances ~2.25 and ~0.9), wide enough (sigma ~0.087) that no jump is beyond 100
// sigmas, an outlier the reference would not reject; group 2 is uniform over [1, 5) (batch variance 4/3:
// every round resets it, keeping nothing).
float jumpingLengths(int k, int round, float u) {
  const float group1[4] = {2.0f, 5.0f, 5.0f, 3.0f};
  if (k == 0) return 2.0f + 0.1f * u;
  if (k == 1) return group1[round] + 0.3f * u;
  return 1.0f + 4.0f * u;
}

TEST_F(LengthCacheGpu, GaussianCountsItsResetsAsTheReferenceDoes) {
  EXPECT_EQ(learnAndCompare(ctx(), KeyStrategy::Gaussian, 1, jumpingLengths, 0.5f), 6u);
  EXPECT_EQ(learnAndCompare(ctx(), KeyStrategy::Gaussian, 1, jumpingLengths, 1e30f), 0u);
}

TEST_F(LengthCacheGpu, OnlyGaussianResets) {
  EXPECT_EQ(learnAndCompare(ctx(), KeyStrategy::Average, 1, jumpingLengths, 0.5f), 0u);
  EXPECT_EQ(learnAndCompare(ctx(), KeyStrategy::Ema, 1, jumpingLengths, 0.5f), 0u);
}

TEST_F(LengthCacheGpu, LearningIsDeterministicAndSkipsMissesAndDeadPaths) {
  Scene scene = boxScene();
  const uint32_t n = 4000;
  HostPaths paths = randomPaths(scene, n, 11);
  setHits(paths, 8.0f, 12, 0.3f);
  Settings s;
  s.strategy = KeyStrategy::Gaussian;
  std::vector<gpu::GpuCacheEntry> runs[2];
  for (auto& run : runs) {
    FakeFrame frame(ctx(), scene, n);
    KeyStage stage(ctx(), scene, {5, 2, 3}, s, n);
    for (int round = 0; round < 3; ++round) {
      frame.upload(paths);
      runLearn(ctx(), stage, frame, n);
    }
    run = stage.downloadCache().entries;
    // A bounce of only misses and dead paths, and bounce 0, teach nothing.
    HostPaths nothing = paths;
    for (size_t i = 0; i < n; ++i) {
      if (i % 2) nothing.alive[i] = 0;
      else nothing.hitT[i] = -1.0f;
    }
    frame.upload(nothing);
    runLearn(ctx(), stage, frame, n);
    frame.upload(paths);
    runLearn(ctx(), stage, frame, n, 0);
    auto after = stage.downloadCache().entries;
    ASSERT_EQ(std::memcmp(after.data(), run.data(), run.size() * sizeof(run[0])), 0);
  }
  ASSERT_EQ(runs[0].size(), runs[1].size());
  EXPECT_EQ(std::memcmp(runs[0].data(), runs[1].data(), runs[0].size() * sizeof(runs[0][0])), 0);
}

TEST_F(LengthCacheGpu, GaussianRejectsOutliersAndResetsWideCells) {
  Scene scene = boxScene();
  Groups g = threeGroups(50);
  const uint32_t n = static_cast<uint32_t>(g.paths.size());
  FakeFrame frame(ctx(), scene, n);
  Settings s;
  s.strategy = KeyStrategy::Gaussian;
  s.gaussOutlier = 3.0f;
  s.gaussReset = INFINITY;
  KeyStage stage(ctx(), scene, {5, 2, 3}, s, n);
  auto entryOf = [&](int k) {
    LengthCache::Contents c = stage.downloadCache();
    KeyEnv env;
    env.slotKeys = c.slotKeys;
    env.slotValues = c.slotValues;
    glm::vec3 o(g.paths.origin[k * 50]), d(g.paths.direction[k * 50]);
    return c.entries[cacheEntry(stage.params().cache, env, stage.params().grid, stage.grid().cell(o), d)];
  };
  for (uint32_t i = 0; i < n; ++i) g.paths.hitT[i] = 2.0f + 0.01f * float(i % 7);
  frame.upload(g.paths);
  runLearn(ctx(), stage, frame, n);
  EXPECT_EQ(entryOf(0).count, 50u);
  g.paths.hitT[0] = 9.0f;  // far beyond 3 sigma (sigma ~ 0.02, floor 0.0126)
  frame.upload(g.paths);
  runLearn(ctx(), stage, frame, n);
  EXPECT_EQ(stage.cacheOutliersRejected(), 1u);
  EXPECT_EQ(entryOf(0).count, 99u);
  EXPECT_NEAR(entryOf(0).mean, 2.03f, 0.01f);

  // A tiny reset threshold: the wide new batch alone is above it too, so the cell empties.
  s.gaussReset = 1e-4f;
  s.gaussOutlier = 100.0f;
  stage.configure(s, {5, 2, 3});  // thresholds only: what was learned stays
  EXPECT_EQ(entryOf(1).count, 100u);
  for (uint32_t i = 0; i < n; ++i) g.paths.hitT[i] = 1.0f + float(i % 5);
  frame.upload(g.paths);
  EXPECT_EQ(frame.counter(1, RL_COUNTER_CACHE_RESETS), 0u) << "nothing was reset so far";
  runLearn(ctx(), stage, frame, n);
  EXPECT_EQ(entryOf(1).count, 0u);
  EXPECT_EQ(frame.counter(1, RL_COUNTER_CACHE_RESETS), 3u) << "one reset per group's entry";
}

}  // namespace
}  // namespace raylab::test
