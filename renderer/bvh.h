// Binned SAH BVH built on the CPU and flattened into the node layout the shaders traverse
// (shaders/shared_types.h: BvhNode). Triangles are reordered into leaf order.
#pragma once

#include <cstdint>
#include <vector>

#include "scenes/scene.h"
#include "shaders/shared_types.h"

namespace raylab {

struct BvhBuildStats {
  uint32_t nodeCount = 0;
  uint32_t leafCount = 0;
  uint32_t maxDepth = 0;
  double buildMs = 0.0;
};

struct Bvh {
  std::vector<gpu::BvhNode> nodes;         // node 0 is the root
  std::vector<uint32_t> triangleOrder;     // BVH position -> index into Scene::triangles
  BvhBuildStats stats;
};

// Depth stays below the shaders' traversal stack (RL_BVH_STACK); leaves hold at most `maxLeafSize`
// triangles unless that depth limit forces a bigger one.
Bvh buildBvh(const std::vector<Triangle>& triangles, uint32_t maxLeafSize = 4);

}  // namespace raylab
