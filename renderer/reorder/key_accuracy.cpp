#include "renderer/reorder/key_accuracy.h"

#include <algorithm>
#include <cmath>
#include <unordered_set>
#include <vector>

#include "shaders/shared_types.h"

namespace raylab {

KeyAccuracy measureKeyAccuracy(const KeyGrid& grid, const KeyAccuracyInput& in, uint32_t bounce, uint32_t keyBits,
                               uint64_t cacheBytes, double cacheOccupancy) {
  KeyAccuracy a;
  a.bounce = bounce;
  a.keyBits = keyBits;
  a.cacheBytes = cacheBytes;
  a.cacheOccupancy = cacheOccupancy;
  size_t n = std::min({in.origin.size(), in.direction.size(), in.predictedLength.size(), in.hitT.size(),
                       in.alive.size()});
  // A degenerate scene has no diagonal to normalize by; report absolute distances then.
  double diagonal = grid.sceneDiagonal > 0.0f ? grid.sceneDiagonal : 1.0;
  std::vector<double> errors;
  uint32_t sameCell = 0;
  for (size_t i = 0; i < n; ++i) {
    if (in.alive[i] == 0) continue;
    ++a.livePaths;
    float predicted = in.predictedLength[i];
    if (!(predicted >= 0.0f)) continue;
    float t = in.hitT[i];
    if (!(t > 0.0f && t < 1e30f)) {
      ++a.misses;
      continue;
    }
    glm::vec3 o(in.origin[i]);
    glm::vec3 d(in.direction[i]);
    glm::vec3 estimated = o + predicted * d;
    glm::vec3 actual = o + t * d;
    double error = glm::length(glm::dvec3(estimated) - glm::dvec3(actual)) / diagonal;
    if (!std::isfinite(error)) continue;  // a NaN direction: no meaningful distance
    errors.push_back(error);
    sameCell += grid.cell(estimated) == grid.cell(actual) ? 1u : 0u;
  }
  a.evaluated = static_cast<uint32_t>(errors.size());
  if (!errors.empty()) {
    double sum = 0.0;
    for (double e : errors) sum += e;
    a.meanError = sum / double(errors.size());
    size_t mid = errors.size() / 2;
    std::nth_element(errors.begin(), errors.begin() + mid, errors.end());
    double median = errors[mid];
    if (errors.size() % 2 == 0) median = 0.5 * (median + *std::max_element(errors.begin(), errors.begin() + mid));
    a.medianError = median;
    a.cellHitRate = double(sameCell) / double(errors.size());
  }
  std::unordered_set<uint32_t> distinct;
  for (size_t i = 0; i < in.keys.size(); ++i)
    if (in.keys[i] != RL_DEAD_KEY) distinct.insert(in.keys[i]);
  a.distinctKeys = static_cast<uint32_t>(distinct.size());
  return a;
}

nlohmann::json toJson(const KeyAccuracy& a) {
  return {{"bounce", a.bounce},
          {"live_paths", a.livePaths},
          {"evaluated", a.evaluated},
          {"misses", a.misses},
          {"mean_error", a.meanError},
          {"median_error", a.medianError},
          {"cell_hit_rate", a.cellHitRate},
          {"distinct_keys", a.distinctKeys},
          {"key_bits", a.keyBits},
          {"cache_bytes", a.cacheBytes},
          {"cache_occupancy", a.cacheOccupancy}};
}

}  // namespace raylab
