// How good a key strategy's length estimate is, per bounce: the distance from the estimated end point
// O + predicted * D to the actual hit point O + t * D over the scene diagonal, and how often both fall in
// the same grid cell. Computed on the host from arrays the renderer downloads when --stats asks for them:
// the rays of one bounce (current set, after its trace) with the prediction made for them at the previous
// bounce's key stage (predictedLength travels with the path through the reorder).
#pragma once

#include <cstdint>
#include <span>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "renderer/reorder/key_grid.h"

namespace raylab {

struct KeyAccuracyInput {
  std::span<const glm::vec4> origin;      // xyz ray origin
  std::span<const glm::vec4> direction;   // xyz ray direction
  std::span<const float> predictedLength; // negative: the strategy predicts no length
  std::span<const float> hitT;            // actual hit distance, negative on a miss
  std::span<const uint32_t> alive;
  std::span<const uint32_t> keys;         // the key stage's output for this bounce (any order); may be empty
};

struct KeyAccuracy {
  uint32_t bounce = 0;
  uint32_t livePaths = 0;     // alive paths
  uint32_t evaluated = 0;     // alive, with a prediction and a hit: the paths the figures below describe
  uint32_t misses = 0;        // alive with a prediction but no hit (no actual point to compare with)
  double meanError = 0.0;     // mean |estimated - actual end point| / scene diagonal
  double medianError = 0.0;
  double cellHitRate = 0.0;   // fraction of evaluated paths whose estimated cell is the actual cell
  uint32_t distinctKeys = 0;  // distinct keys of live paths (RL_DEAD_KEY excluded)
  uint32_t keyBits = 0;
  uint64_t cacheBytes = 0;
  double cacheOccupancy = 0.0;
};

// Arrays are read up to the shortest of origin, direction, predictedLength, hitT and alive.
KeyAccuracy measureKeyAccuracy(const KeyGrid& grid, const KeyAccuracyInput& input, uint32_t bounce,
                               uint32_t keyBits, uint64_t cacheBytes, double cacheOccupancy);

nlohmann::json toJson(const KeyAccuracy& a);

}  // namespace raylab
