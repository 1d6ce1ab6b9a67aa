#include "renderer/bvh/bvh_pairs.h"

#include <limits>
#include <stdexcept>
#include <string>

namespace raylab {
namespace {

void setChild(gpu::BvhPairNode& pair, int slot, const gpu::BvhNode& child, uint32_t pairIndex) {
  // The traversal carries a leaf child as one word (RL_LEAF_TAG): its first entry and count must fit it.
  if (child.triCount > (1u << RL_LEAF_COUNT_BITS) || (child.triCount > 0 && child.leftOrFirst >= RL_LEAF_ENTRY_LIMIT))
    throw std::invalid_argument("pairNodes: a leaf of " + std::to_string(child.triCount) + " triangles from entry " +
                                std::to_string(child.leftOrFirst) + " does not fit the traversal's leaf word (at most " +
                                std::to_string(1u << RL_LEAF_COUNT_BITS) + " triangles, entries below " +
                                std::to_string(RL_LEAF_ENTRY_LIMIT) + ")");
  float* x = &pair.xBounds.x;
  float* y = &pair.yBounds.x;
  float* z = &pair.zBounds.x;
  x[2 * slot] = child.boundsMin.x, x[2 * slot + 1] = child.boundsMax.x;
  y[2 * slot] = child.boundsMin.y, y[2 * slot + 1] = child.boundsMax.y;
  z[2 * slot] = child.boundsMin.z, z[2 * slot + 1] = child.boundsMax.z;
  pair.child[slot] = child.triCount > 0 ? RL_LEAF_WORD(child.leftOrFirst, child.triCount) : pairIndex;
}

// A slot without a child: RL_BVH_NO_CHILD behind a box at +infinity on every axis, which no ray enters. Each
// slab's two distances are then the same infinity (the traversal's inverse direction is never 0), so the entry is
// +inf or the exit -inf: the traversal need not check the word.
void setNoChild(gpu::BvhPairNode& pair, int slot) {
  const float inf = std::numeric_limits<float>::infinity();
  for (float* axis : {&pair.xBounds.x, &pair.yBounds.x, &pair.zBounds.x}) axis[2 * slot] = axis[2 * slot + 1] = inf;
  pair.child[slot] = RL_BVH_NO_CHILD;
}

}  // namespace

std::vector<gpu::BvhPairNode> pairNodes(const Bvh& bvh) {
  if (bvh.nodes.empty()) throw std::invalid_argument("pairNodes: a BVH without a root");
  const gpu::BvhNode& root = bvh.nodes[0];
  if (bvh.nodes.size() == 1 || root.triCount > 0 || isEmptyTree(bvh.nodes)) {
    gpu::BvhPairNode only{};
    for (int slot = 0; slot < 2; ++slot) {
      if (root.triCount > 0) setChild(only, slot, root, 0);
      else setNoChild(only, slot);
    }
    return {only};
  }
  // Interior binary nodes in array order get consecutive pair indices (the root's is 0).
  std::vector<uint32_t> pairOf(bvh.nodes.size(), RL_BVH_NO_CHILD);
  uint32_t pairs = 0;
  for (size_t i = 0; i < bvh.nodes.size(); ++i)
    if (bvh.nodes[i].triCount == 0) pairOf[i] = pairs++;
  std::vector<gpu::BvhPairNode> out(pairs);
  for (size_t i = 0; i < bvh.nodes.size(); ++i) {
    const gpu::BvhNode& n = bvh.nodes[i];
    if (n.triCount > 0) continue;
    for (uint32_t slot = 0; slot < 2; ++slot) {
      const uint32_t c = n.leftOrFirst + slot;
      if (c >= bvh.nodes.size()) throw std::invalid_argument("pairNodes: a child past the node array");
      setChild(out[pairOf[i]], int(slot), bvh.nodes[c], pairOf[c]);
    }
  }
  return out;
}

}  // namespace raylab
