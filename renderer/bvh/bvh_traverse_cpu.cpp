#include "renderer/bvh/bvh_traverse_cpu.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace raylab {
namespace {

float cpuIntersectBox(glm::vec3 bmin, glm::vec3 bmax, glm::vec3 origin, glm::vec3 invDir, float tMax) {
  const glm::vec3 t0 = (bmin - origin) * invDir;
  const glm::vec3 t1 = (bmax - origin) * invDir;
  const glm::vec3 tn = glm::min(t0, t1);
  const glm::vec3 tf = glm::max(t0, t1);
  const float enter = std::max(std::max(tn.x, tn.y), std::max(tn.z, 0.0f));
  const float leave = std::min(std::min(tf.x, tf.y), std::min(tf.z, tMax));
  return enter <= leave ? enter : 1e30f;
}

// shaders/bvh_traverse.glsl's intersectTriangleEdges: no early exit, one test after u, v and t (a ray parallel
// to the plane divides by zero, and the infinities or NaNs fail the test).
void cpuIntersectTriangle(glm::vec3 v0, glm::vec3 e1, glm::vec3 e2, uint32_t index, glm::vec3 origin, glm::vec3 dir,
                          CpuHit& hit, float& tMax) {
  const glm::vec3 p = glm::cross(dir, e2);
  const float inv = 1.0f / glm::dot(e1, p);
  const glm::vec3 s = origin - v0;
  const float u = glm::dot(s, p) * inv;
  const glm::vec3 q = glm::cross(s, e1);
  const float v = glm::dot(dir, q) * inv;
  const float t = glm::dot(e2, q) * inv;
  if (u >= 0.0f && v >= 0.0f && u + v <= 1.0f && t > 0.0f && t < tMax) {
    tMax = t;
    hit.t = t;
    hit.triangle = index;
    hit.bary = {u, v};
  }
}

void cpuIntersectTriangle(const gpu::GpuTriangle& tri, uint32_t index, glm::vec3 origin, glm::vec3 dir, CpuHit& hit,
                          float& tMax) {
  cpuIntersectTriangle(tri.v0, tri.e1, tri.e2, index, origin, dir, hit, tMax);
}

glm::vec3 cpuSafeInverse(glm::vec3 d) {
  const float eps = 1e-20f;
  glm::vec3 r;
  for (int k = 0; k < 3; ++k) r[k] = 1.0f / (std::abs(d[k]) > eps ? d[k] : (d[k] >= 0.0f ? eps : -eps));
  return r;
}

}  // namespace

CpuHit traverseBinaryCpu(const std::vector<gpu::BvhNode>& nodes, const std::vector<gpu::GpuTriangle>& triangles,
                         glm::vec3 origin, glm::vec3 dir, float tMax, bool anyHit) {
  CpuHit hit;
  const glm::vec3 invDir = cpuSafeInverse(dir);
  uint32_t stack[RL_BVH_STACK];
  uint32_t sp = 0, node = 0;
  if (isEmptyTree(nodes)) return hit;  // its inverted boxes would be entered, and its nodes point at each other
  if (cpuIntersectBox(nodes[0].boundsMin, nodes[0].boundsMax, origin, invDir, tMax) >= 1e30f) return hit;
  while (true) {
    hit.steps++;
    hit.nodeVisits++;
    const gpu::BvhNode& n = nodes[node];
    if (n.triCount > 0) {
      hit.triangleTests += n.triCount;
      for (uint32_t i = 0; i < n.triCount; ++i)
        cpuIntersectTriangle(triangles[n.leftOrFirst + i], n.leftOrFirst + i, origin, dir, hit, tMax);
      if (anyHit && hit.t > 0.0f) return hit;
      if (sp == 0) break;
      node = stack[--sp];
      continue;
    }
    uint32_t left = n.leftOrFirst, right = left + 1;
    float dl = cpuIntersectBox(nodes[left].boundsMin, nodes[left].boundsMax, origin, invDir, tMax);
    float dr = cpuIntersectBox(nodes[right].boundsMin, nodes[right].boundsMax, origin, invDir, tMax);
    if (dl > dr) {
      std::swap(dl, dr);
      std::swap(left, right);
    }
    if (dl >= 1e30f) {
      if (sp == 0) break;
      node = stack[--sp];
      continue;
    }
    node = left;
    if (dr < 1e30f && sp < RL_BVH_STACK) stack[sp++] = right;
  }
  return hit;
}

std::vector<uint32_t> PairFetchLog::nodes() const {
  std::vector<uint32_t> read;
  for (uint32_t word : steps)
    if (word < RL_LEAF_TAG) read.push_back(word);
  return read;
}

std::vector<uint32_t> PairFetchLog::entries() const {
  std::vector<uint32_t> read;
  for (uint32_t word : steps)
    if (word >= RL_LEAF_TAG)
      for (uint32_t e = RL_LEAF_FIRST(word); e < RL_LEAF_FIRST(word) + RL_LEAF_COUNT(word); ++e) read.push_back(e);
  return read;
}

CpuHit traversePairsCpu(const std::vector<gpu::BvhPairNode>& nodes, const std::vector<gpu::GpuLeafTriangle>& entries,
                        glm::vec3 origin, glm::vec3 dir, float tMax, bool anyHit, PairFetchLog* log) {
  CpuHit hit;
  if (nodes.empty()) return hit;
  const glm::vec3 invDir = cpuSafeInverse(dir);
  const glm::vec3 originInv = origin * invDir;
  uint32_t stack[RL_BVH_STACK];
  uint32_t sp = 0, node = 0;
  while (true) {
    hit.steps++;
    if (log) log->steps.push_back(node);
    if (node >= RL_LEAF_TAG) {  // a leaf word (isLeafWord): its range of entries
      const uint32_t first = RL_LEAF_FIRST(node), count = RL_LEAF_COUNT(node);
      for (uint32_t e = first; e < first + count; ++e) {
        const gpu::GpuLeafTriangle& t = entries[e];
        hit.triangleTests++;
        cpuIntersectTriangle(t.v0, t.e1, t.e2, t.triangle, origin, dir, hit, tMax);
      }
      if (anyHit && hit.t > 0.0f) return hit;
      if (sp == 0) break;
      node = stack[--sp];
      continue;
    }
    hit.nodeVisits++;
    const gpu::BvhPairNode& n = nodes[node];
    // enterPair: the slabs as bounds * invDir - origin * invDir, both children at once.
    float enter[2], leave[2];
    for (int c = 0; c < 2; ++c) {
      const glm::vec3 lo(n.xBounds[2 * c], n.yBounds[2 * c], n.zBounds[2 * c]);
      const glm::vec3 hi(n.xBounds[2 * c + 1], n.yBounds[2 * c + 1], n.zBounds[2 * c + 1]);
      const glm::vec3 t0 = lo * invDir - originInv, t1 = hi * invDir - originInv;
      const glm::vec3 tn = glm::min(t0, t1), tf = glm::max(t0, t1);
      enter[c] = std::max(std::max(tn.x, tn.y), std::max(tn.z, 0.0f));
      leave[c] = std::min(std::min(tf.x, tf.y), std::min(tf.z, tMax));
    }
    const bool hit0 = enter[0] <= leave[0], hit1 = enter[1] <= leave[1];
    if (hit0 && hit1) {
      const bool firstNearer = enter[0] <= enter[1];
      if (sp < RL_BVH_STACK) stack[sp++] = firstNearer ? n.child[1] : n.child[0];
      node = firstNearer ? n.child[0] : n.child[1];
    } else if (hit0 || hit1) {
      node = hit0 ? n.child[0] : n.child[1];
    } else {
      if (sp == 0) break;
      node = stack[--sp];
    }
  }
  return hit;
}

CpuHit intersectAllCpu(const std::vector<gpu::GpuTriangle>& triangles, glm::vec3 origin, glm::vec3 dir, float tMax) {
  CpuHit hit;
  for (uint32_t i = 0; i < triangles.size(); ++i) cpuIntersectTriangle(triangles[i], i, origin, dir, hit, tMax);
  return hit;
}

CpuHit traverseWideCpu(const BvhWide& bvh, const std::vector<gpu::GpuTriangle>& triangles, glm::vec3 origin,
                       glm::vec3 dir, float tMax, bool anyHit) {
  CpuHit hit;
  const glm::vec3 invDir = cpuSafeInverse(dir);
  const uint32_t octant = (dir.x < 0.0f ? 1u : 0u) | (dir.y < 0.0f ? 2u : 0u) | (dir.z < 0.0f ? 4u : 0u);
  glm::uvec2 stack[RL_BVH_STACK];
  uint32_t sp = 0;
  glm::uvec2 nodeGroup(0u, (1u << 8) | (1u << octant));
  while (true) {
    if ((nodeGroup.y & 0xFFu) == 0) {
      if (sp == 0) break;
      nodeGroup = stack[--sp];
    }
    const uint32_t position = std::countr_zero(nodeGroup.y & 0xFFu);
    nodeGroup.y &= ~(1u << position);
    const uint32_t slot = position ^ octant;
    const uint32_t nodeIndex = nodeGroup.x + std::popcount((nodeGroup.y >> 8) & ((1u << slot) - 1u));

    hit.steps++;
    hit.nodeVisits++;
    const gpu::BvhWideNode& n = bvh.nodes[nodeIndex];
    const uint32_t interiorMask = wideInteriorMask(n);
    uint32_t nodeHits = 0, triangleHits = 0;
    // The ray in the node's quantized frame, as the shader does: a child plane q is at t = q * tScale + tOrigin.
    const glm::vec3 scale = wideScale(n);
    const glm::vec3 tScale = scale * invDir, tOrigin = (n.origin - origin) * invDir;
    for (uint32_t s = 0; s < RL_BVH_WIDTH; ++s) {
      // Near and far planes by the ray's sign per axis, as the shader picks them (no min and max per child).
      const glm::vec3 lo = wideLowPlanes(n, s), hi = wideHighPlanes(n, s);
      glm::vec3 qnear, qfar;
      for (int k = 0; k < 3; ++k) {
        const bool negative = (octant >> k) & 1u;
        qnear[k] = negative ? hi[k] : lo[k];
        qfar[k] = negative ? lo[k] : hi[k];
      }
      const glm::vec3 tn = qnear * tScale + tOrigin, tf = qfar * tScale + tOrigin;
      const float enter = std::max(std::max(tn.x, tn.y), std::max(tn.z, 0.0f));
      const float leave = std::min(std::min(tf.x, tf.y), std::min(tf.z, tMax));
      if (enter > leave) continue;
      if (interiorMask & (1u << s))
        nodeHits |= 1u << (s ^ octant);
      else
        triangleHits |= wideLeafBits(wideMeta(n, s));
    }
    if (nodeHits != 0) {  // descending: the siblings wait on the stack
      if ((nodeGroup.y & 0xFFu) != 0) stack[sp++] = nodeGroup;
      nodeGroup = {n.childBase, (interiorMask << 8) | nodeHits};
    }
    while (triangleHits != 0) {  // the node's triangle group, in the same step
      const uint32_t index = n.triBase + std::countr_zero(triangleHits);
      triangleHits &= triangleHits - 1u;
      hit.triangleTests++;
      cpuIntersectTriangle(triangles[index], index, origin, dir, hit, tMax);
      if (anyHit && hit.t > 0.0f) return hit;
    }
  }
  return hit;
}

}  // namespace raylab
