// Virtual warp efficiency: device-independent SIMT coherence from per-path loop counts.
// For each group of W consecutive threads in dispatch order, efficiency = sum(n_i) / (W * max n_i); the
// frame's figure weights each warp by W * max n_i, i.e. sum(n_i) / sum(W * max n_i) over all warps.
#pragma once

#include <cstddef>
#include <cstdint>

namespace raylab {

struct WarpEfficiency {
  double efficiency = 1.0;  // 1 when no warp did any work
  double meanSteps = 0.0;   // mean n_i over all threads
};

WarpEfficiency virtualWarpEfficiency(const uint32_t* steps, size_t count, uint32_t warpWidth);

}  // namespace raylab
