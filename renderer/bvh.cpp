#include "renderer/bvh.h"

#include <algorithm>
#include <array>
#include <chrono>

namespace raylab {
namespace {

constexpr int kBins = 16;
constexpr uint32_t kMaxDepth = RL_BVH_STACK - 2;

float surfaceArea(const Bounds& b) {
  if (b.empty()) return 0.0f;
  glm::vec3 e = b.extent();
  return 2.0f * (e.x * e.y + e.y * e.z + e.z * e.x);
}

struct Builder {
  const std::vector<Triangle>& tris;
  std::vector<Bounds> triBounds;
  std::vector<glm::vec3> centroids;
  std::vector<uint32_t> order;
  std::vector<gpu::BvhNode> nodes;
  uint32_t maxLeaf;
  BvhBuildStats stats;

  Bounds rangeBounds(uint32_t first, uint32_t count, Bounds* centroidBounds) const {
    Bounds b, c;
    for (uint32_t i = first; i < first + count; ++i) {
      b.grow(triBounds[order[i]]);
      c.grow(centroids[order[i]]);
    }
    if (centroidBounds) *centroidBounds = c;
    return b;
  }

  void makeLeaf(uint32_t node, uint32_t first, uint32_t count) {
    nodes[node].leftOrFirst = first;
    nodes[node].triCount = count;
    stats.leafCount++;
  }

  // Returns the split position in [first, first+count) or 0 when a leaf is cheaper.
  uint32_t findSplit(uint32_t first, uint32_t count, const Bounds& nodeBounds, const Bounds& cb) {
    float nodeArea = surfaceArea(nodeBounds);
    float bestCost = nodeArea * static_cast<float>(count);  // cost of a leaf, in triangle tests
    int bestAxis = -1, bestBin = 0;
    for (int axis = 0; axis < 3; ++axis) {
      float lo = cb.min[axis], hi = cb.max[axis];
      if (!(hi > lo)) continue;
      std::array<Bounds, kBins> binBounds;
      std::array<uint32_t, kBins> binCount{};
      float scale = kBins / (hi - lo);
      for (uint32_t i = first; i < first + count; ++i) {
        uint32_t t = order[i];
        int b = std::min(kBins - 1, static_cast<int>((centroids[t][axis] - lo) * scale));
        binBounds[b].grow(triBounds[t]);
        binCount[b]++;
      }
      std::array<float, kBins> rightCost{};
      Bounds acc;
      uint32_t n = 0;
      for (int b = kBins - 1; b > 0; --b) {
        acc.grow(binBounds[b]);
        n += binCount[b];
        rightCost[b] = surfaceArea(acc) * static_cast<float>(n);
      }
      acc = Bounds();
      n = 0;
      for (int b = 0; b < kBins - 1; ++b) {
        acc.grow(binBounds[b]);
        n += binCount[b];
        // One interior-node visit costs about one triangle test.
        float cost = nodeArea + surfaceArea(acc) * static_cast<float>(n) + rightCost[b + 1];
        if (n > 0 && n < count && cost < bestCost) {
          bestCost = cost;
          bestAxis = axis;
          bestBin = b;
        }
      }
    }
    if (bestAxis < 0) return 0;
    float lo = cb.min[bestAxis];
    float scale = kBins / (cb.max[bestAxis] - lo);
    auto mid = std::partition(order.begin() + first, order.begin() + first + count, [&](uint32_t t) {
      return std::min(kBins - 1, static_cast<int>((centroids[t][bestAxis] - lo) * scale)) <= bestBin;
    });
    return static_cast<uint32_t>(mid - order.begin());
  }

  void build(uint32_t node, uint32_t first, uint32_t count, uint32_t depth) {
    stats.maxDepth = std::max(stats.maxDepth, depth);
    Bounds cb;
    Bounds b = rangeBounds(first, count, &cb);
    nodes[node].boundsMin = b.min;
    nodes[node].boundsMax = b.max;
    uint32_t split = 0;
    if (count > 1 && depth < kMaxDepth) split = findSplit(first, count, b, cb);
    // Split by median on the widest centroid axis when SAH prefers a leaf that is too large.
    if (split == 0 && count > maxLeaf && depth < kMaxDepth) {
      glm::vec3 e = cb.extent();
      int axis = e.x > e.y ? (e.x > e.z ? 0 : 2) : (e.y > e.z ? 1 : 2);
      split = first + count / 2;
      std::nth_element(order.begin() + first, order.begin() + split, order.begin() + first + count,
                       [&](uint32_t a, uint32_t c) { return centroids[a][axis] < centroids[c][axis]; });
    }
    if (split == 0 || split == first || split == first + count) {
      makeLeaf(node, first, count);
      return;
    }
    uint32_t left = static_cast<uint32_t>(nodes.size());
    nodes.resize(nodes.size() + 2);
    nodes[node].leftOrFirst = left;
    nodes[node].triCount = 0;
    build(left, first, split - first, depth + 1);
    build(left + 1, split, first + count - split, depth + 1);
  }
};

}  // namespace

Bvh buildBvh(const std::vector<Triangle>& triangles, uint32_t maxLeafSize) {
  auto start = std::chrono::steady_clock::now();
  Builder b{triangles, {}, {}, {}, {}, std::max(1u, maxLeafSize), {}};
  b.triBounds.resize(triangles.size());
  b.centroids.resize(triangles.size());
  b.order.resize(triangles.size());
  for (size_t i = 0; i < triangles.size(); ++i) {
    for (const glm::vec3& v : triangles[i].v) b.triBounds[i].grow(v);
    b.centroids[i] = b.triBounds[i].center();
    b.order[i] = static_cast<uint32_t>(i);
  }
  b.nodes.reserve(2 * triangles.size() + 1);
  b.nodes.resize(1);
  if (triangles.empty()) {
    // An empty scene still gets a root that no ray enters.
    b.nodes[0] = {glm::vec3(1e30f), 0u, glm::vec3(-1e30f), 0u};
    b.nodes.push_back(b.nodes[0]);
    b.nodes.push_back(b.nodes[0]);
    b.nodes[0].leftOrFirst = 1;
  } else {
    b.build(0, 0, static_cast<uint32_t>(triangles.size()), 0);
  }
  Bvh bvh;
  bvh.nodes = std::move(b.nodes);
  bvh.triangleOrder = std::move(b.order);
  bvh.stats = b.stats;
  bvh.stats.nodeCount = static_cast<uint32_t>(bvh.nodes.size());
  bvh.stats.buildMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return bvh;
}

}  // namespace raylab
