// The detailed statistics of a bounce as the GPU reduces them (shaders/detail_types.h): the plain C++ twin
// of every detail pass, adding to the same integer sums from host arrays (tests compare the two sum for
// sum), and the figures both are turned into (FrameStats' warp efficiency, prediction error, cell hit rate,
// distinct keys, cache occupancy).
#pragma once

#include <cstdint>
#include <span>

#include <glm/glm.hpp>

#include "renderer/reorder/key_grid.h"
#include "shaders/detail_types.h"

namespace raylab {

// A bounce's rays after its trace, in slot order (the path-state layout unpacked: shared_types.h).
struct PredictionInput {
  std::span<const glm::vec4> origin;       // xyz ray origin
  std::span<const glm::vec4> direction;    // xyz unit ray direction
  std::span<const float> predictedLength;  // the key stage's prediction; negative: none
  std::span<const float> hitT;             // actual hit distance, negative on a miss
  std::span<const uint32_t> alive;         // nonzero: a live path
};

// 1 / the grid's scene diagonal (1 for a degenerate scene): what prediction errors are normalized by.
float inverseDiagonal(const KeyGrid& grid);

// The twins of detail_warps.comp, detail_prediction.comp, detail_keys.comp and detail_cache.comp.
void addWarpSums(gpu::GpuDetailSums& sums, std::span<const uint32_t> steps);
// Arrays are read up to the shortest of them.
void addPredictionSums(gpu::GpuDetailSums& sums, const KeyGrid& grid, const PredictionInput& in);
// `liveBits`: the bits a live key uses (KeyStage::keyBits() - 1).
void addDistinctKeys(gpu::GpuDetailSums& sums, std::span<const uint32_t> keys, uint32_t liveBits);
void addCacheUsed(gpu::GpuDetailSums& sums, std::span<const gpu::GpuCacheEntry> entries);

// Bits a live key drops so that it fits the distinct-key bitmap (detail_keys.comp's keyShift).
uint32_t distinctKeyShift(uint32_t liveBits);

// The histogram bin of an error >= 0, and the midpoint of a bin's range (bin 0 starts at 0).
uint32_t errorBin(float error);
double errorBinMidpoint(uint32_t bin);

struct WarpFigures {
  double efficiency = 1.0;  // work / slots; 1 when no warp did any work
  double meanSteps = 0.0;   // work / slot count
};
WarpFigures warpFigures(const gpu::GpuDetailSums& sums, uint64_t slotCount);

struct PredictionFigures {
  uint32_t livePaths = 0, evaluated = 0, misses = 0;
  double meanError = 0.0;    // of the evaluated paths, in scene diagonals (each clamped to RL_DETAIL_ERROR_MAX)
  double medianError = 0.0;  // the lower median's histogram bin midpoint (within 0.8%)
  double cellHitRate = 0.0;  // sameCell / evaluated
};
// Zeros when nothing was evaluated.
PredictionFigures predictionFigures(const gpu::GpuDetailSums& sums);

}  // namespace raylab
