// Plain C++ twins of the shaders' BVH traversals (shaders/bvh_traverse.glsl and bvh_traverse_wide.glsl), float
// for float, so tests can check the wide tree against the binary one without a device. Keep them in step with
// the GLSL: same box and triangle tests, same visit order, same step counting.
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
// Every triangle tested, no tree: the reference both trees are checked against (the binary traversal's exact
// boxes can miss a hit on a box face that a ray parallel to it grazes; the wide tree's boxes, rounded outwards,
// rarely have that face).
CpuHit intersectAllCpu(const std::vector<gpu::GpuTriangle>& triangles, glm::vec3 origin, glm::vec3 dir, float tMax);
CpuHit traverseWideCpu(const BvhWide& bvh, const std::vector<gpu::GpuTriangle>& triangles, glm::vec3 origin,
                       glm::vec3 dir, float tMax, bool anyHit);

}  // namespace raylab
