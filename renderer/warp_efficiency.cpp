#include "renderer/warp_efficiency.h"

#include <algorithm>

namespace raylab {

WarpEfficiency virtualWarpEfficiency(const uint32_t* steps, size_t count, uint32_t warpWidth) {
  WarpEfficiency w;
  if (count == 0 || warpWidth == 0) return w;
  uint64_t work = 0, slots = 0;
  for (size_t start = 0; start < count; start += warpWidth) {
    size_t end = std::min(count, start + warpWidth);
    uint32_t mx = 0;
    for (size_t i = start; i < end; ++i) {
      work += steps[i];
      mx = std::max(mx, steps[i]);
    }
    // A partial last warp still occupies W lanes on the device.
    slots += static_cast<uint64_t>(warpWidth) * mx;
  }
  w.efficiency = slots > 0 ? static_cast<double>(work) / static_cast<double>(slots) : 1.0;
  w.meanSteps = static_cast<double>(work) / static_cast<double>(count);
  return w;
}

}  // namespace raylab
