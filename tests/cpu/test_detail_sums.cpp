// The detailed statistics' plain C++ twins (renderer/detail_sums.h) on hand-made arrays, values worked out by
// hand: virtual warp efficiency (per warp of 32 consecutive slots sum(n_i) / (32 * max n_i), the frame
// weighted by 32 * max n_i), prediction error, cell hit rate, the median's histogram, distinct keys.
// tests/gpu/test_detail_stats.cpp checks the GPU passes against these sum for sum.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "renderer/detail_sums.h"

namespace raylab {
namespace {

WarpFigures warpsOf(const std::vector<uint32_t>& steps) {
  gpu::GpuDetailSums sums{};
  addWarpSums(sums, steps);
  return warpFigures(sums, steps.size());
}

}  // namespace

TEST(DetailSums, UniformWorkIsFullyEfficient) {
  const WarpFigures w = warpsOf(std::vector<uint32_t>(64, 7));
  EXPECT_DOUBLE_EQ(w.efficiency, 1.0);
  EXPECT_DOUBLE_EQ(w.meanSteps, 7.0);
}

TEST(DetailSums, WarpsAreWeightedByTheirSlots) {
  // Warp 0: one slot of 4, 31 of 0 -> 4 of 128 slots. Warp 1: 32 slots of 2 -> 64 of 64. Frame: 68 / 192.
  std::vector<uint32_t> steps(64, 0);
  steps[0] = 4;
  for (size_t i = 32; i < 64; ++i) steps[i] = 2;
  const WarpFigures w = warpsOf(steps);
  EXPECT_DOUBLE_EQ(w.efficiency, 68.0 / 192.0);
  EXPECT_DOUBLE_EQ(w.meanSteps, 68.0 / 64.0);
}

TEST(DetailSums, PartialLastWarpStillOccupiesAllLanes) {
  // 33 slots: warp 0 is 32 ones (32 of 32), warp 1 is a 3 alone (3 of 96). Frame: 35 / 128.
  std::vector<uint32_t> steps(33, 1);
  steps[32] = 3;
  EXPECT_DOUBLE_EQ(warpsOf(steps).efficiency, 35.0 / 128.0);
}

TEST(DetailSums, NoWorkAndNoSlots) {
  EXPECT_DOUBLE_EQ(warpsOf(std::vector<uint32_t>(40, 0)).efficiency, 1.0);
  const WarpFigures none = warpsOf({});
  EXPECT_DOUBLE_EQ(none.efficiency, 1.0);
  EXPECT_DOUBLE_EQ(none.meanSteps, 0.0);
}

TEST(DetailSums, PredictionFiguresOnHandMadeArrays) {
  Bounds b;
  b.min = glm::vec3(0);
  b.max = glm::vec3(6, 8, 0);  // diagonal 10 (z flat)
  Settings s;
  s.grid.automatic = false;
  s.grid.cells = {6, 8, 1};
  const KeyGrid grid = makeKeyGrid(b, {}, s);
  ASSERT_NEAR(grid.sceneDiagonal, 10.0f, 1e-5f);
  std::vector<glm::vec4> origin(6, glm::vec4(0.5f, 0.5f, 0, 0));
  std::vector<glm::vec4> dir(6, glm::vec4(1, 0, 0, 0));
  std::vector<float> predicted = {2.0f, 3.0f, 1.0f, -1.0f, 2.0f, 5.0f};
  std::vector<float> hit = {2.0f, 2.0f, 4.0f, 3.0f, -1.0f, 1.0f};  // errors 0, 0.1, 0.3; none; a miss; dead
  std::vector<uint32_t> alive = {1, 1, 1, 1, 1, 0};
  gpu::GpuDetailSums sums{};
  addPredictionSums(sums, grid, {origin, dir, predicted, hit, alive});
  const PredictionFigures p = predictionFigures(sums);
  EXPECT_EQ(p.livePaths, 5u);
  EXPECT_EQ(p.evaluated, 3u);
  EXPECT_EQ(p.misses, 1u);
  EXPECT_NEAR(p.meanError, 0.4 / 3.0, 1e-6);
  EXPECT_NEAR(p.medianError, 0.1, 0.1 / 128.0);  // the bin midpoint: within 2^-7 of the error
  EXPECT_DOUBLE_EQ(p.cellHitRate, 1.0 / 3.0);     // only the exact prediction lands in the actual cell
  alive.assign(6, 0);
  gpu::GpuDetailSums dead{};
  addPredictionSums(dead, grid, {origin, dir, predicted, hit, alive});
  EXPECT_EQ(predictionFigures(dead).evaluated, 0u);
  EXPECT_EQ(predictionFigures(dead).medianError, 0.0);
}

// Every error in [2^-20, 2^11.9) lies in the bin errorBin gives it, whose midpoint is within 2^-7 of it;
// bins grow with the error; smaller errors go to bin 0 (read as 0), larger ones to the last bin.
TEST(DetailSums, ErrorHistogramBinsHoldTheirErrors) {
  uint32_t last = 0;
  for (double e = std::ldexp(1.0, RL_DETAIL_BIN_MIN_EXPONENT); e < 3800.0; e *= 1.0123) {
    const uint32_t bin = errorBin(float(e));
    EXPECT_GE(bin, last) << e;
    last = bin;
    EXPECT_NEAR(errorBinMidpoint(bin), double(float(e)), double(float(e)) / 128.0) << e;
  }
  EXPECT_EQ(errorBin(0.0f), 0u);
  EXPECT_EQ(errorBin(1e-9f), 0u);
  EXPECT_EQ(errorBinMidpoint(0), 0.0);
  EXPECT_EQ(errorBin(1e9f), RL_DETAIL_ERROR_BINS - 1);
}

// The median is the lower one, over the histogram: of 4 errors 0.01, 0.02, 0.5, 0.9 it is 0.02's bin.
TEST(DetailSums, MedianIsTheLowerMiddleError) {
  gpu::GpuDetailSums sums{};
  for (float e : {0.9f, 0.01f, 0.5f, 0.02f}) ++sums.errorBins[errorBin(e)], ++sums.evaluated;
  EXPECT_NEAR(predictionFigures(sums).medianError, 0.02, 0.02 / 128.0);
}

TEST(DetailSums, DistinctKeysSkipTheDeadKeyAndDropBitsPastTheBitmap) {
  gpu::GpuDetailSums sums{};
  addDistinctKeys(sums, std::vector<uint32_t>{4, 4, 9, RL_DEAD_KEY, 1}, 9);
  EXPECT_EQ(sums.distinctKeys, 3u);
  // 31-bit keys drop one bit: 6 and 7 become one key.
  EXPECT_EQ(distinctKeyShift(31), 1u);
  gpu::GpuDetailSums wide{};
  addDistinctKeys(wide, std::vector<uint32_t>{6, 7, 8}, 31);
  EXPECT_EQ(wide.distinctKeys, 2u);
}

TEST(DetailSums, CacheEntriesWithSamples) {
  std::vector<gpu::GpuCacheEntry> entries(5);
  entries[1].count = 3;
  entries[4].count = 1;
  gpu::GpuDetailSums sums{};
  addCacheUsed(sums, entries);
  EXPECT_EQ(sums.cacheUsed, 2u);
}

}  // namespace raylab
