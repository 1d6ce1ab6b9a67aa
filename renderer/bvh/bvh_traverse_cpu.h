// Plain C++ twins of the shaders' BVH traversals (shaders/bvh_traverse.glsl and bvh_traverse_wide.glsl), float
// for float, so tests can check the trees against each other and count what a traversal reads without a device.
// traversePairsCpu walks the pair nodes the shader reads; traverseBinaryCpu the BvhNode tree they are made from,
// in the loop the shader had before them. Keep them in step with the GLSL: same box and triangle tests, same
// visit order, same step counting.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/bvh/bvh.h"
#include "renderer/bvh/bvh_wide.h"
#include "shaders/shared_types.h"

namespace raylab {

struct CpuHit {
  float t = -1.0f;  // negative: no hit
  uint32_t triangle = 0;  // BVH-order triangle index
  glm::vec2 bary{0.0f};
  uint32_t steps = 0;  // loop iterations: nodes visited (binary: interior nodes and leaves; wide: wide nodes)
  // What the traversal fetched: nodes visited (binary: one 32-byte node, an interior one's two children read
  // besides; wide: one 80-byte node), wide leaf records read (8 bytes; none since the wide leaves are triangle
  // ranges of their node) and triangles tested (48 bytes each).
  uint32_t nodeVisits = 0, leafRecords = 0, triangleTests = 0;
};

// `triangles` in BVH order (bvhOrderTriangles); anyHit stops at the first hit, as shadow rays do.
CpuHit traverseBinaryCpu(const std::vector<gpu::BvhNode>& nodes, const std::vector<gpu::GpuTriangle>& triangles,
                         glm::vec3 origin, glm::vec3 dir, float tMax, bool anyHit);
// What a pair-node traversal read, in order: each pair node it tested (64 bytes: both children's boxes) and each
// leaf entry it intersected (48 bytes). The lanes of a warp that walk the same part of the tree share these reads.
struct PairFetchLog {
  std::vector<uint32_t> steps;  // each step's word: a pair-node index, or a leaf's word (RL_LEAF_WORD)
  // What the steps read, in order: the pair nodes (the steps that are not leaf words), and the leaf entries
  // (every entry of each leaf step's range: the shader tests a leaf's triangles all, any-hit rays too).
  std::vector<uint32_t> nodes() const;
  std::vector<uint32_t> entries() const;
};
// bvh_traverse.glsl's traverseBvh over the tree the GPU reads (pairNodes and leafRecords): hit.triangle is the
// entry's BVH-order index, steps count pair nodes and leaves visited as the shader's do, nodeVisits the pair nodes
// and triangleTests the entries. `log`, when given, gets every fetch appended.
CpuHit traversePairsCpu(const std::vector<gpu::BvhPairNode>& nodes, const std::vector<gpu::GpuLeafTriangle>& entries,
                        glm::vec3 origin, glm::vec3 dir, float tMax, bool anyHit, PairFetchLog* log = nullptr);
// Every triangle tested, no tree: the reference both trees are checked against (the binary traversal's exact
// boxes can miss a hit on a box face that a ray parallel to it grazes; the wide tree's boxes, rounded outwards,
// rarely have that face).
CpuHit intersectAllCpu(const std::vector<gpu::GpuTriangle>& triangles, glm::vec3 origin, glm::vec3 dir, float tMax);
CpuHit traverseWideCpu(const BvhWide& bvh, const std::vector<gpu::GpuTriangle>& triangles, glm::vec3 origin,
                       glm::vec3 dir, float tMax, bool anyHit);

}  // namespace raylab
