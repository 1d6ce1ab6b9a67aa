// The binary BVH the shaders traverse (shaders/shared_types.h: BvhNode), built on the CPU by Embree's
// rtcBuildBVH (binned SAH, multi-threaded; with spatial splits on request) and flattened into our node layout.
// Triangles are reordered into leaf order.
#pragma once

#include <cstdint>
#include <vector>

#include "scenes/scene.h"
#include "shaders/shared_types.h"

namespace raylab {

struct BvhBuildStats {
  uint32_t nodeCount = 0;
  uint32_t leafCount = 0;
  uint32_t maxDepth = 0;      // of the deepest leaf; the root is depth 0
  uint32_t largestLeaf = 0;   // triangles in the biggest leaf
  uint32_t maxLeafSize = 0;   // the leaf-size limit the build ended with (above the requested one only
                              // where the depth limit forced it)
  uint32_t references = 0;    // leaf entries: the triangle count without spatial splits, more with them
  double sahCost = 0.0;       // renderer/bvh/bvh_sah.h's cost with both costs 1
  double buildMs = 0.0;       // the whole buildBvh call: Embree device, build and flattening (not the
                              // sahCost statistic, computed after it)
  // Its phases (wall ms), for finding where a build's time goes: the primitives' boxes (and the scene's),
  // Embree's rtcBuildBVH (device creation included), the flattening into our layout.
  double primitivesMs = 0.0;
  double embreeMs = 0.0;
  double flattenMs = 0.0;
};

// Node 0 is the root. An interior node (triCount == 0) has its children at leftOrFirst and leftOrFirst + 1;
// a leaf holds triangles leftOrFirst .. leftOrFirst + triCount - 1 in BVH order. Nodes are laid out depth
// first, each pair of siblings adjacent. Without spatial splits every triangle appears exactly once, so
// triangleOrder is a permutation (the BVH order every consumer shares: see bvh.cpp); with them a triangle cut
// by a split plane sits in the leaves of both sides, each leaf's box bounding only its part.
struct Bvh {
  std::vector<gpu::BvhNode> nodes;         // node 0 is the root
  std::vector<uint32_t> triangleOrder;     // BVH position (leaf entry) -> index into Scene::triangles
  BvhBuildStats stats;
};

// buildBvh's tree for a scene without triangles: a root with inverted bounds (min above max) over two children
// alike. A min/max slab test still enters an inverted box, so every reader asks this first.
inline bool isEmptyTree(const std::vector<gpu::BvhNode>& nodes) {
  return nodes.empty() || nodes[0].boundsMin.x > nodes[0].boundsMax.x;
}

// Spatial splits (Stich, Friedrich and Dietrich, HPG 2009: the SBVH): Embree's high-quality build, which may
// also split a triangle's box at a plane when that lowers the SAH cost more than splitting the list does.
// References grow by at most kSpatialSplitBudget of the triangle count.
enum class BvhSplits { None, Spatial };
constexpr double kSpatialSplitBudget = 0.5;
// The spatial-split tree is the default layout's, so its SAH weighs a triangle test 1.5 interior-node visits
// and its leaves hold at most 4 triangles: over the lean pair-node loop (4ad3790) a node visit costs less than
// a triangle test. On the H200 against 1.0 and 8: Sponza's bounce rays 1.86 -> 1.92 G rays/s (1.0 and 4: 1.89),
// the megakernel 2.7% shorter; weights 0.5 lost 9-16% of bounce rays, 2.0 was level with 1.5; leaves of 4 made
// the clutter room's frames 3-5% shorter (docs/results/h200-lean-steps, run3.sh). The plain tree (the binary
// layout's, and the wide collapse's source) keeps 1.0 and kDefaultMaxLeafSize.
constexpr float kSpatialSplitIntersectionCost = 1.5f;
constexpr uint32_t kSpatialSplitMaxLeafSize = 4;

// Depth stays below the shaders' traversal stack (RL_BVH_STACK); the SAH chooses each leaf's size up to
// `maxLeafSize` triangles (at most 32, Embree's limit), unless the depth limit forces bigger leaves. No
// triangles: a root whose inverted box no ray enters. Throws std::invalid_argument for a non-finite vertex
// (the scene loaders refuse those already) and std::runtime_error if Embree fails. `threads`: for the phases
// around Embree's build (Embree has its own); 0: the hardware's, fewer for small scenes. The tree is the same
// for every count (the tests compare them).
constexpr uint32_t kDefaultMaxLeafSize = 8;
// The deepest a leaf may lie (the root is depth 0): below the shaders' traversal stack, which holds a path's
// pending siblings. buildBvh gives Embree this limit; reinsertOptimize keeps its trees within it.
constexpr uint32_t kMaxBvhDepth = RL_BVH_STACK - 2;
// `presplit` (spatial splits only): cuts before the build, as a fraction of the triangle count (bvh_presplit.h).
Bvh buildBvh(const std::vector<Triangle>& triangles, uint32_t maxLeafSize = kDefaultMaxLeafSize, uint32_t threads = 0,
             BvhSplits splits = BvhSplits::None, double presplit = 0.0);

}  // namespace raylab
