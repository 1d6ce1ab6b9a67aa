// The detail passes (shaders/detail_*.comp through renderer/detail_stats.h) against their plain C++ twins
// (renderer/detail_sums.h), sum for sum, on random arrays shaped like a bounce's: slots past a warp boundary,
// dead paths, no prediction, misses, errors from far below to far above the histogram's range, keys with
// repeats and the dead key, and keys wider than the bitmap. (Rendered frames' detailed figures, whole and in
// steps, are compared in test_render_invariant.cpp's SteppedFramesKeepDetailedStatistics.)
#include <gtest/gtest.h>

#include <bit>
#include <random>
#include <vector>

#include "renderer/detail_stats.h"
#include "renderer/detail_sums.h"
#include "renderer/reorder/key_grid.h"
#include "renderer/vk/gpu_buffer.h"
#include "tests/gpu_test.h"

namespace raylab::test {
namespace {

class DetailPasses : public GpuTest {
 protected:
  template <class T>
  static GpuBuffer uploaded(const std::vector<T>& v) {
    GpuBuffer b(ctx(), std::max<size_t>(v.size(), 1) * sizeof(T));
    if (!v.empty()) b.uploadVector(v);
    return b;
  }
};

void expectSameSums(const gpu::GpuDetailSums& gpu, const gpu::GpuDetailSums& cpu) {
  EXPECT_EQ(gpu.warpWorkLo, cpu.warpWorkLo);
  EXPECT_EQ(gpu.warpWorkHi, cpu.warpWorkHi);
  EXPECT_EQ(gpu.warpSlotsLo, cpu.warpSlotsLo);
  EXPECT_EQ(gpu.warpSlotsHi, cpu.warpSlotsHi);
  EXPECT_EQ(gpu.livePaths, cpu.livePaths);
  EXPECT_EQ(gpu.evaluated, cpu.evaluated);
  EXPECT_EQ(gpu.misses, cpu.misses);
  EXPECT_EQ(gpu.sameCell, cpu.sameCell);
  EXPECT_EQ(gpu.errorLo, cpu.errorLo);
  EXPECT_EQ(gpu.errorHi, cpu.errorHi);
  EXPECT_EQ(gpu.distinctKeys, cpu.distinctKeys);
  EXPECT_EQ(gpu.cacheUsed, cpu.cacheUsed);
  for (uint32_t b = 0; b < RL_DETAIL_ERROR_BINS; ++b) EXPECT_EQ(gpu.errorBins[b], cpu.errorBins[b]) << "bin " << b;
}

}  // namespace

TEST_F(DetailPasses, MatchTheirTwinsSumForSum) {
  // More slots than RL_DETAIL_MAX_GROUPS groups cover at once (each group loops), not a multiple of a warp.
  const uint32_t n = RL_DETAIL_MAX_GROUPS * RL_DETAIL_GROUP_SIZE + 1000 + 7;
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  Bounds bounds;
  bounds.min = glm::vec3(-3, 0, -2);
  bounds.max = glm::vec3(5, 4, 6);
  Settings settings;
  const KeyGrid grid = makeKeyGrid(bounds, glm::vec3(0, 1, 0), settings);

  std::vector<uint32_t> steps(n), keys(n);
  std::vector<glm::vec4> origin(n), direction(n), throughput(n);
  std::vector<float> hitT(n), predicted(n);
  std::vector<uint32_t> alive(n);
  for (uint32_t i = 0; i < n; ++i) {
    steps[i] = rng() % 200;
    glm::vec3 d = glm::normalize(glm::vec3(unit(rng) - 0.5f, unit(rng) - 0.5f, unit(rng) - 0.5f) + 1e-3f);
    glm::vec3 o = bounds.min + (bounds.max - bounds.min) * glm::vec3(unit(rng), unit(rng), unit(rng));
    alive[i] = rng() % 10 != 0;
    const uint32_t id = alive[i] ? i : RL_DEAD_PATH;
    origin[i] = glm::vec4(o, 0.0f);
    direction[i] = glm::vec4(d, std::bit_cast<float>(id));
    // Predictions: none, exact, near, far off, absurd (past the clamp); hits: misses among them.
    const uint32_t kind = rng() % 6;
    hitT[i] = rng() % 8 == 0 ? -1.0f : 0.01f + 9.0f * unit(rng);
    predicted[i] = kind == 0   ? -1.0f
                   : kind == 1 ? hitT[i]
                   : kind == 2 ? hitT[i] + 1e-7f * unit(rng)
                   : kind == 3 ? 20.0f * unit(rng)
                   : kind == 4 ? 1e6f * unit(rng)
                               : 1e30f;
    throughput[i] = glm::vec4(1.0f, 1.0f, 1.0f, predicted[i]);
    keys[i] = rng() % 7 == 0 ? RL_DEAD_KEY : (rng() % 5000) * 977u;  // repeats; spread over 23 bits
  }
  std::vector<uint32_t> wideKeys = keys;
  for (uint32_t& k : wideKeys)
    if (k != RL_DEAD_KEY) k = (k * 2654435761u) & 0x7FFFFFFFu;  // 31 live bits: past the bitmap
  std::vector<gpu::GpuCacheEntry> entries(3001);
  for (auto& e : entries) e.count = rng() % 3 == 0 ? 0u : 1u + rng() % 9;

  GpuBuffer stepsBuf = uploaded(steps), keysBuf = uploaded(keys), wideKeysBuf = uploaded(wideKeys);
  GpuBuffer originBuf = uploaded(origin), directionBuf = uploaded(direction), throughputBuf = uploaded(throughput);
  GpuBuffer hitTBuf = uploaded(hitT), entriesBuf = uploaded(entries);
  gpu::GpuFrame frame{};
  frame.state[1] = {originBuf.address(), directionBuf.address(), throughputBuf.address()};
  frame.hits.t = hitTBuf.address();
  frame.pathCount = n;
  GpuBuffer frameBuf = uploaded(std::vector<gpu::GpuFrame>{frame});
  gpu::GpuKeyParams params{};
  params.grid = grid.gpu;
  params.cache.entries = entriesBuf.address();
  params.cache.entryCount = uint32_t(entries.size());
  GpuBuffer paramsBuf = uploaded(std::vector<gpu::GpuKeyParams>{params});

  DetailStats details(ctx());
  ctx().submitAndWait([&](VkCommandBuffer cmd) {
    details.recordClear(cmd, 3);
    details.recordWarps(cmd, stepsBuf.address(), n, 0, nullptr);
    details.recordPrediction(cmd, frameBuf.address(), paramsBuf.address(), 1, n, inverseDiagonal(grid), 1, nullptr);
    details.recordDistinctKeys(cmd, keysBuf.address(), n, 23, 1, nullptr);
    details.recordDistinctKeys(cmd, wideKeysBuf.address(), n, 31, 2, nullptr);
    details.recordCacheUsed(cmd, paramsBuf.address(), uint32_t(entries.size()), nullptr);
    details.recordToHost(cmd);
    VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0, nullptr,
                         0, nullptr);
  });

  gpu::GpuDetailSums cpu[3] = {};
  addWarpSums(cpu[0], steps);
  addCacheUsed(cpu[0], entries);
  addPredictionSums(cpu[1], grid, {origin, direction, predicted, hitT, alive});
  addDistinctKeys(cpu[1], keys, 23);
  addDistinctKeys(cpu[2], wideKeys, 31);
  for (uint32_t b = 0; b < 3; ++b) {
    SCOPED_TRACE("bounce " + std::to_string(b));
    expectSameSums(details.sums(b), cpu[b]);
  }
  // The arrays exercise what they should: every kind of path, a spread of errors, the dropped key bit.
  EXPECT_GT(cpu[1].misses, 0u);
  EXPECT_GT(cpu[1].sameCell, 0u);
  EXPECT_LT(cpu[1].sameCell, cpu[1].evaluated);
  EXPECT_GT(cpu[1].errorBins[0], 0u);
  EXPECT_GT(cpu[1].errorBins[RL_DETAIL_ERROR_BINS - 1], 0u);
  EXPECT_TRUE(details.measuredWarps(0));
  EXPECT_FALSE(details.measuredPrediction(0));
  EXPECT_TRUE(details.measuredPrediction(1));
  EXPECT_FALSE(details.measuredPrediction(2));  // keys without the rays' pass: no prediction figures
}

}  // namespace raylab::test
