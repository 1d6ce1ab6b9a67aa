// The length cache on the GPU: its learning matches a double-precision reference for average, ema and
// gaussian, is deterministic, skips misses and dead paths, rejects outliers and resets high-variance cells.
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

struct Reference {
  double count = 0, mean = 0, m2 = 0;
};

// learnEvery > 1: only slots i with (i + frameIndex + bounce) % learnEvery == 0 learn (Settings::learnEvery),
// the frame index moving each round so the sampled slots change; the reference takes the same slots.
void learnAndCompare(const VulkanContext& ctx, KeyStrategy strategy, uint32_t learnEvery = 1) {
  Scene scene = boxScene();
  const uint32_t per = 300;
  Groups g = threeGroups(per);
  const uint32_t n = static_cast<uint32_t>(g.paths.size());
  FakeFrame frame(ctx, scene, n);
  Settings s;
  s.strategy = strategy;
  s.gaussOutlier = 100.0f;  // no outliers, no resets: the plain statistics
  s.gaussReset = INFINITY;
  s.emaAlpha = 0.01f;
  s.learnEvery = learnEvery;
  KeyStage stage(ctx, scene, {5, 2, 3}, s, n);
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  Reference ref[3];
  for (int round = 0; round < 4; ++round) {
    double bsum[3] = {}, bsq[3] = {}, bn[3] = {};
    const uint32_t frameIndex = 3 + round, bounce = 1;
    for (uint32_t i = 0; i < n; ++i) {
      float t = 1.0f + 2.0f * g.group[i] + (0.5f + round * 0.1f) * u(rng);
      g.paths.hitT[i] = t;
      if ((i + frameIndex + bounce) % learnEvery != 0) continue;
      bsum[g.group[i]] += t, bsq[g.group[i]] += double(t) * t, bn[g.group[i]] += 1;
    }
    for (int k = 0; k < 3; ++k) {
      double mb = bsum[k] / bn[k], m2b = bsq[k] - bsum[k] * mb;
      Reference& r = ref[k];
      if (r.count == 0) {
        r = {bn[k], mb, m2b};
      } else if (strategy == KeyStrategy::Ema) {
        r.mean += (1.0 - std::pow(1.0 - s.emaAlpha, bn[k])) * (mb - r.mean);
        r.count += bn[k];
      } else {
        double nn = r.count + bn[k], d = mb - r.mean;
        r.m2 += m2b + d * d * r.count * bn[k] / nn;
        r.mean += d * bn[k] / nn;
        r.count = nn;
      }
    }
    frame.upload(g.paths, frameIndex);
    runLearn(ctx, stage, frame, n, bounce);
  }
  LengthCache::Contents c = stage.downloadCache();
  KeyEnv env;
  env.slotKeys = c.slotKeys;
  env.slotValues = c.slotValues;
  for (int k = 0; k < 3; ++k) {
    uint32_t i = k * per;
    glm::vec3 o(g.paths.origin[i]), d(g.paths.direction[i]);
    int32_t e = cacheEntry(stage.params().cache, env, stage.params().grid, stage.grid().cell(o), d);
    ASSERT_GE(e, 0) << "group " << k;
    const gpu::GpuCacheEntry& entry = c.entries[e];
    EXPECT_EQ(entry.count, uint32_t(ref[k].count)) << toString(strategy);
    EXPECT_NEAR(entry.mean, ref[k].mean, 1e-5 * ref[k].mean) << toString(strategy);
    if (strategy == KeyStrategy::Gaussian) {
      EXPECT_NEAR(entry.m2, ref[k].m2, 1e-3 * ref[k].m2);
      EXPECT_NEAR(entry.sigma, std::sqrt(ref[k].m2 / (ref[k].count - 1)), 1e-3);
    }
  }
  // 3 groups x 1 octant each of the 8 x occupied entries.
  EXPECT_NEAR(stage.cacheOccupancy(), 3.0 / c.entries.size(), 1e-12);
  EXPECT_GT(stage.cacheMemoryBytes(), c.entries.size() * 36);
}

TEST_F(LengthCacheGpu, AverageMatchesReference) { learnAndCompare(ctx(), KeyStrategy::Average); }
TEST_F(LengthCacheGpu, EmaMatchesReference) { learnAndCompare(ctx(), KeyStrategy::Ema); }
TEST_F(LengthCacheGpu, GaussianMatchesReference) { learnAndCompare(ctx(), KeyStrategy::Gaussian); }
TEST_F(LengthCacheGpu, SampledAverageMatchesReference) { learnAndCompare(ctx(), KeyStrategy::Average, 3); }
TEST_F(LengthCacheGpu, SampledGaussianMatchesReference) { learnAndCompare(ctx(), KeyStrategy::Gaussian, 7); }

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
  runLearn(ctx(), stage, frame, n);
  EXPECT_EQ(entryOf(1).count, 0u);
}

}  // namespace
}  // namespace raylab::test
