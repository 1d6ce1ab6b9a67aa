#include "renderer/bvh/bvh_leaf_records.h"

#include <stdexcept>
#include <string>

namespace raylab {

std::vector<gpu::GpuLeafTriangle> leafRecords(const std::vector<Triangle>& triangles,
                                              const std::vector<uint32_t>& entries,
                                              const std::vector<uint32_t>& bvhOrder) {
  constexpr uint32_t kAbsent = 0xFFFFFFFFu;
  std::vector<uint32_t> bvhIndexOf(triangles.size(), kAbsent);
  for (uint32_t i = 0; i < bvhOrder.size(); ++i) {
    if (bvhOrder[i] >= triangles.size())
      throw std::invalid_argument("leafRecords: BVH-order slot " + std::to_string(i) + " names no triangle");
    bvhIndexOf[bvhOrder[i]] = i;
  }
  std::vector<gpu::GpuLeafTriangle> records;
  records.reserve(entries.size());
  for (uint32_t src : entries) {
    if (src >= triangles.size() || bvhIndexOf[src] == kAbsent)
      throw std::invalid_argument("leafRecords: a leaf entry names triangle " + std::to_string(src) +
                                  ", which the BVH order lacks");
    const Triangle& t = triangles[src];
    records.push_back({t.v[0], bvhIndexOf[src], t.v[1] - t.v[0], 0u, t.v[2] - t.v[0], 0u});
  }
  return records;
}

}  // namespace raylab
