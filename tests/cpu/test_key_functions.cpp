// The C++ key functions on their own: shared layouts, the deterministic arithmetic against <cmath>, key
// ranges and finiteness on awkward inputs, and the prediction-accuracy figures on hand-made arrays.
#include <cmath>
#include <cstddef>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "renderer/reorder/key_functions.h"
#include "renderer/reorder/key_grid.h"
#include "renderer/reorder/key_strategies.h"

namespace raylab {
namespace {

using namespace gpu;
// Scalar layout: vec3/uvec3 take 12 bytes at 4-byte alignment, buffer addresses 8 at 8.
static_assert(sizeof(GpuKeyGrid) == 80);
static_assert(offsetof(GpuKeyGrid, cells) == 32);
static_assert(offsetof(GpuKeyGrid, cacheCells) == 64);
static_assert(sizeof(GpuCacheEntry) == 16);
static_assert(sizeof(GpuCacheBatch) == 20);
static_assert(sizeof(GpuLengthCache) == 5 * 8 + 10 * 4);
static_assert(offsetof(GpuKeyParams, cache) == 80);
static_assert(offsetof(GpuKeyParams, oracleT) == 160);
static_assert(sizeof(GpuKeyParams) == 176);
static_assert(sizeof(KeyPush) == 48);
static_assert(sizeof(KeyLearnPush) == 32);

TEST(KeyFunctions, DeterministicMathMatchesCmath) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int i = 0; i < 100000; ++i) {
    float x = std::exp2((u(rng) - 0.5f) * 190.0f);  // 1e-29 .. 1e29
    EXPECT_NEAR(detRcp(x) * x, 1.0f, 1e-6f);
    float y = u(rng) * 40.0f;
    EXPECT_NEAR(detSqrt(y), std::sqrt(y), 2e-6f * (1.0f + std::sqrt(y)));
    float p = 1.0f - u(rng);
    EXPECT_NEAR(detLn(p), std::log(p), 2e-6f * (1.0f + std::abs(std::log(p))));
    float c = u(rng) * 3.0f - 1.0f;
    EXPECT_NEAR(detCos2Pi(c), std::cos(2.0 * M_PI * c), 2e-6f);
  }
  EXPECT_EQ(detSqrt(0.0f), 0.0f);
  EXPECT_EQ(detSqrt(-1.0f), 0.0f);
  EXPECT_EQ(detLn(1.0f), 0.0f);
}

TEST(KeyFunctions, GaussianSampleIsStandardNormal) {
  uint32_t state = rngSeed(12, 3, 1, 7, RL_RNG_KEY);
  double sum = 0, sum2 = 0;
  int within1 = 0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    float z = gaussianSample(state);
    ASSERT_TRUE(std::isfinite(z));
    sum += z;
    sum2 += double(z) * z;
    within1 += std::abs(z) < 1.0f;
  }
  EXPECT_NEAR(sum / n, 0.0, 0.01);
  EXPECT_NEAR(sum2 / n, 1.0, 0.02);
  EXPECT_NEAR(double(within1) / n, 0.6827, 0.01);
}

TEST(KeyFunctions, KeyWidthsPerStrategy) {
  Settings s;
  s.grid.automatic = false;
  s.grid.cells = {1024, 1024, 1024};
  Bounds b;
  b.min = glm::vec3(0);
  b.max = glm::vec3(1);
  GpuKeyGrid g = makeKeyGrid(b, {}, s).gpu;
  EXPECT_EQ(keyWidth(KeyStrategy::None, g), 0u);
  EXPECT_EQ(keyWidth(KeyStrategy::DeadLast, g), 1u);
  EXPECT_EQ(keyWidth(KeyStrategy::Fixed, g), 31u);
  EXPECT_EQ(keyWidth(KeyStrategy::Direction, g), 31u);
  EXPECT_EQ(keyWidth(KeyStrategy::OriginDirection, g), 32u);  // 50 bits of code, top 31 kept
  EXPECT_EQ(keyWidth(KeyStrategy::TwoPoint, g), 24u);  // top 23 bits: three radix passes with the dead bit
}

TEST(KeyFunctions, OctahedralCellsCoverTheSquareAndStayInRange) {
  const glm::vec3 dirs[] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1},
                            {1, 1, 1}, {-1, -1, -1}, {1e-20f, 0, -1}, {-0.0f, -0.0f, -1}};
  for (glm::vec3 d : dirs) {
    glm::uvec2 c = octahedralCell(d, 5, 4);
    EXPECT_LT(c.x, 32u);
    EXPECT_LT(c.y, 16u);
  }
  EXPECT_EQ(octahedralCell({0, 0, 1}, 4, 4), glm::uvec2(8, 8));  // +z is the centre
  EXPECT_NE(octahedralCell({1, 0.1f, 0.5f}, 4, 4), octahedralCell({-1, 0.1f, 0.5f}, 4, 4));
  EXPECT_EQ(octant({-1, 2, -3}), 5u);
  EXPECT_EQ(octant({std::nanf(""), -1, 0}), 2u);
}

// Every strategy on random and hostile inputs: keys in range, lengths finite, dead paths last.
TEST(KeyFunctions, KeysStayInRangeOnHostileInputs) {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  const glm::vec3 origins[] = {{1, 1, 1}, {nan, 0, 0}, {inf, -inf, 0}, {1e30f, 5, 5}, {-3, 20, 4}};
  const glm::vec3 dirs[] = {{0, 0, 1}, {nan, nan, nan}, {0, 0, 0}, {inf, 0, 0}, {1e-35f, 0, 0}, {0.6f, -0.8f, 0}};
  const float oracle[] = {-1.0f, 0.0f, 3.0f, inf, nan};
  Bounds b;
  b.min = glm::vec3(0);
  b.max = glm::vec3(10, 4, 6);
  for (glm::uvec3 cells : {glm::uvec3(1), glm::uvec3(7, 3, 100), glm::uvec3(1024)}) {
    Settings s;
    s.grid.automatic = false;
    s.grid.cells = cells;
    GpuKeyParams p{};
    p.grid = makeKeyGrid(b, {}, s).gpu;
    p.fixedLength = 5.0f;
    p.cache.lengthMax = 20.0f;
    for (KeyStrategy strategy : allKeyStrategies()) {
      if (strategy == KeyStrategy::None) continue;
      uint32_t bits = keyWidth(strategy, p.grid);
      for (glm::vec3 o : origins)
        for (glm::vec3 d : dirs)
          for (float t : oracle)
            for (uint32_t alive : {0u, 1u}) {
              float len = 0;
              uint32_t key = computeKey(strategyId(strategy), p, KeyEnv{}, {o, d, 9, t}, alive, len);
              ASSERT_TRUE(std::isfinite(len)) << toString(strategy);
              if (alive) {
                ASSERT_LT(uint64_t(key), uint64_t(1) << (bits - 1)) << toString(strategy);
              } else {
                ASSERT_EQ(key, RL_DEAD_KEY);
              }
            }
    }
  }
}

// The strategy table's "reads the fixed length" and "uses the grid" are what the key functions do: with an
// empty length cache and an oracle miss, a strategy's predicted length follows the fixed length exactly when
// the table says it reads it, and its key changes with the grid's resolution exactly when it uses the grid.
TEST(KeyStrategyTable, SaysWhatTheKeyFunctionsRead) {
  Bounds b;
  b.min = glm::vec3(0);
  b.max = glm::vec3(10, 4, 6);
  auto keyOf = [&](KeyStrategy strategy, float fixedLength, uint32_t cells, float& len) {
    Settings s;
    s.grid.automatic = false;
    s.grid.cells = glm::uvec3(cells);
    GpuKeyParams p{};
    p.grid = makeKeyGrid(b, {}, s).gpu;
    p.fixedLength = fixedLength;
    p.cache.lengthMax = 20.0f;
    const KeyPath path{{1.3f, 1.1f, 0.7f}, glm::normalize(glm::vec3(0.6f, 0.3f, 0.74f)), 9, -1.0f};  // a miss
    return computeKey(strategyId(strategy), p, KeyEnv{}, path, 1u, len);
  };
  for (const KeyStrategyInfo& info : kKeyStrategies) {
    if (info.strategy == KeyStrategy::None) continue;
    float shortLen = 0, longLen = 0, coarseLen = 0;
    const uint32_t shortKey = keyOf(info.strategy, 1.0f, 16, shortLen);
    const uint32_t longKey = keyOf(info.strategy, 7.0f, 16, longLen);
    const uint32_t coarseKey = keyOf(info.strategy, 1.0f, 2, coarseLen);
    EXPECT_EQ(shortLen != longLen, info.readsFixedLength) << info.name << ": length " << shortLen << " vs " << longLen;
    if (info.readsFixedLength) {
      EXPECT_NE(shortKey, longKey) << info.name;
    }
    EXPECT_EQ(shortKey != coarseKey, info.usesGrid) << info.name;
    EXPECT_EQ(strategyId(info.strategy), info.shaderId);
    EXPECT_EQ(parseKeyStrategy(info.name), info.strategy);
  }
}

}  // namespace
}  // namespace raylab
