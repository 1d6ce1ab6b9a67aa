#include "renderer/detail_sums.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <vector>

#include "renderer/reorder/key_functions.h"

namespace raylab {
namespace {

uint64_t join(uint32_t lo, uint32_t hi) { return uint64_t(hi) << 32 | lo; }

void add64(uint32_t& lo, uint32_t& hi, uint64_t v) {
  const uint64_t sum = join(lo, hi) + v;
  lo = uint32_t(sum);
  hi = uint32_t(sum >> 32);
}

}  // namespace

void addWarpSums(gpu::GpuDetailSums& sums, std::span<const uint32_t> steps) {
  uint64_t work = 0, slots = 0;
  for (size_t start = 0; start < steps.size(); start += RL_VIRTUAL_WARP) {
    const size_t end = std::min(steps.size(), start + RL_VIRTUAL_WARP);
    uint32_t most = 0;
    for (size_t i = start; i < end; ++i) work += steps[i], most = std::max(most, steps[i]);
    slots += uint64_t(RL_VIRTUAL_WARP) * most;  // a partial last warp still occupies a whole warp
  }
  add64(sums.warpWorkLo, sums.warpWorkHi, work);
  add64(sums.warpSlotsLo, sums.warpSlotsHi, slots);
}

// Bin 0 holds errors below 2^RL_DETAIL_BIN_MIN_EXPONENT (reported as 0: below the resolution); bin b >= 1 the
// errors whose float bits, shifted to exponent and top mantissa bits, are b - 1 past the range's start.
uint32_t errorBin(float error) {
  constexpr int first = (127 + RL_DETAIL_BIN_MIN_EXPONENT) << RL_DETAIL_BIN_MANTISSA_BITS;
  const int b = int(std::bit_cast<uint32_t>(error) >> (23u - RL_DETAIL_BIN_MANTISSA_BITS)) - first + 1;
  return uint32_t(std::clamp(b, 0, int(RL_DETAIL_ERROR_BINS) - 1));
}

double errorBinMidpoint(uint32_t bin) {
  if (bin == 0) return 0.0;
  constexpr uint32_t first = (127 + RL_DETAIL_BIN_MIN_EXPONENT) << RL_DETAIL_BIN_MANTISSA_BITS;
  auto lowerBound = [&](uint32_t b) {
    return double(std::bit_cast<float>((b - 1 + first) << (23u - RL_DETAIL_BIN_MANTISSA_BITS)));
  };
  return 0.5 * (lowerBound(bin) + lowerBound(bin + 1));
}

float inverseDiagonal(const KeyGrid& grid) { return grid.sceneDiagonal > 0.0f ? 1.0f / grid.sceneDiagonal : 1.0f; }

void addPredictionSums(gpu::GpuDetailSums& sums, const KeyGrid& grid, const PredictionInput& in) {
  const size_t n = std::min({in.origin.size(), in.direction.size(), in.predictedLength.size(), in.hitT.size(),
                             in.alive.size()});
  // The same float operations as detail_prediction.comp.
  const float invDiagonal = inverseDiagonal(grid);
  uint64_t errorSum = 0;
  for (size_t i = 0; i < n; ++i) {
    if (in.alive[i] == 0) continue;
    ++sums.livePaths;
    const float predicted = in.predictedLength[i];
    if (!(predicted >= 0.0f)) continue;
    const float t = in.hitT[i];
    if (!(t > 0.0f && t < 1e30f)) {
      ++sums.misses;
      continue;
    }
    const float error = std::abs(predicted - t) * invDiagonal;
    if (!(error < 1e30f)) continue;
    ++sums.evaluated;
    errorSum += uint64_t(std::min(error, float(RL_DETAIL_ERROR_MAX)) * float(1u << RL_DETAIL_ERROR_FRACTION_BITS));
    ++sums.errorBins[errorBin(error)];
    const KeyPath path{glm::vec3(in.origin[i]), glm::vec3(in.direction[i]), 0u, -1.0f};
    if (grid.cell(endPoint(path, predicted)) == grid.cell(endPoint(path, t))) ++sums.sameCell;
  }
  add64(sums.errorLo, sums.errorHi, errorSum);
}

uint32_t distinctKeyShift(uint32_t liveBits) {
  return liveBits > RL_DETAIL_KEY_BITMAP_BITS ? liveBits - RL_DETAIL_KEY_BITMAP_BITS : 0u;
}

void addDistinctKeys(gpu::GpuDetailSums& sums, std::span<const uint32_t> keys, uint32_t liveBits) {
  const uint32_t shift = distinctKeyShift(liveBits);
  std::vector<uint32_t> seen;
  seen.reserve(keys.size());
  for (uint32_t k : keys)
    if (k != RL_DEAD_KEY) seen.push_back(k >> shift);
  std::sort(seen.begin(), seen.end());
  sums.distinctKeys += uint32_t(std::unique(seen.begin(), seen.end()) - seen.begin());
}

void addCacheUsed(gpu::GpuDetailSums& sums, std::span<const gpu::GpuCacheEntry> entries) {
  for (const gpu::GpuCacheEntry& e : entries) sums.cacheUsed += e.count > 0u ? 1u : 0u;
}

WarpFigures warpFigures(const gpu::GpuDetailSums& sums, uint64_t slotCount) {
  WarpFigures w;
  const uint64_t work = join(sums.warpWorkLo, sums.warpWorkHi), slots = join(sums.warpSlotsLo, sums.warpSlotsHi);
  w.efficiency = slots > 0 ? double(work) / double(slots) : 1.0;
  w.meanSteps = slotCount > 0 ? double(work) / double(slotCount) : 0.0;
  return w;
}

PredictionFigures predictionFigures(const gpu::GpuDetailSums& sums) {
  PredictionFigures p;
  p.livePaths = sums.livePaths;
  p.evaluated = sums.evaluated;
  p.misses = sums.misses;
  if (sums.evaluated == 0) return p;
  p.meanError = std::ldexp(double(join(sums.errorLo, sums.errorHi)), -RL_DETAIL_ERROR_FRACTION_BITS) / sums.evaluated;
  p.cellHitRate = double(sums.sameCell) / double(sums.evaluated);
  // The lower median: the error of rank (evaluated - 1) / 2, counting from 0.
  const uint64_t rank = (sums.evaluated - 1) / 2;
  uint64_t below = 0;
  for (uint32_t b = 0; b < RL_DETAIL_ERROR_BINS; ++b) {
    below += sums.errorBins[b];
    if (below > rank) {
      p.medianError = errorBinMidpoint(b);
      break;
    }
  }
  return p;
}

}  // namespace raylab
