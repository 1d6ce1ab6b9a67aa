// The leaf entries of a binary tree as its GPU traversal reads them (shaders/shared_types.h, GpuLeafTriangle):
// each entry's triangle with its BVH-order index. The tree without spatial splits reads its own order (entry i is
// BVH-order triangle i); a tree with them names scene triangles, several entries one triangle, which are mapped
// to the index the BVH order gives them, so a hit reports the same triangle whichever binary tree found it.
#pragma once

#include <cstdint>
#include <vector>

#include "scenes/scene.h"
#include "shaders/shared_types.h"

namespace raylab {

// `entries`: a tree's leaf entries (Bvh::triangleOrder: entry -> scene triangle); `bvhOrder`: the BVH order
// (BVH-order index -> scene triangle, a permutation). The floats are bvhOrderTriangles' (v0, v1 - v0, v2 - v0),
// so both binary trees test the same triangle the same way. Throws std::invalid_argument for an entry or a
// BVH-order slot outside `triangles`, or an entry whose triangle the BVH order lacks.
std::vector<gpu::GpuLeafTriangle> leafRecords(const std::vector<Triangle>& triangles,
                                              const std::vector<uint32_t>& entries,
                                              const std::vector<uint32_t>& bvhOrder);

}  // namespace raylab
