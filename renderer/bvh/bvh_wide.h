// The compressed 8-wide BVH (shaders/shared_types.h: BvhWideNode) made by collapsing a binary Bvh, whoever
// built it: each wide node takes up to 8 subtrees of the binary tree, chosen greedily (opening the largest-area
// interior child until 8 or only leaves remain, within the node's leaf budget) or by the SAH (bvh_wide_slots.h),
// quantizes their boxes outwards and places them in direction slots. A leaf slot holds up to 8 triangles: a
// binary leaf (greedy), or all the triangles under a binary node (SAH); a binary leaf of more than 8 takes
// several slots (one per 8), with one box. The collapse moves each binary leaf, whole, so that a wide node's
// leaves lie in one block of the BVH-order triangles, and rewrites the binary tree's leaf ranges and
// triangleOrder to match (the binary tree, its traversal and every consumer of the BVH order see the same
// leaves at their new place).
#pragma once

#include <cstdint>
#include <vector>

#include "renderer/bvh/bvh.h"
#include "renderer/settings/settings.h"
#include "shaders/shared_types.h"

namespace raylab {

// A slot's triangle count fits 3 bits (1..8); a node's leaf block, its triangle mask, 32 triangles.
constexpr uint32_t kWideLeafSlotTriangles = 8;
constexpr uint32_t kWideNodeTriangles = 32;
// The slots a leaf of `triangles` takes: one per 8.
constexpr uint32_t wideLeafSlots(uint32_t triangles) {
  return (triangles + kWideLeafSlotTriangles - 1) / kWideLeafSlotTriangles;
}

struct BvhWideStats {
  uint32_t nodeCount = 0;
  uint32_t leafCount = 0;  // leaf slots (a binary leaf of more than 8 triangles takes several)
  uint32_t maxDepth = 0;   // root = 0; the traversal stack holds at most maxDepth + 1 groups
  double buildMs = 0.0;    // the collapse only
  // Bytes of the tree itself (its nodes: no leaf records), without the triangles.
  uint64_t treeBytes() const { return uint64_t(nodeCount) * sizeof(gpu::BvhWideNode); }
};

struct BvhWide {
  std::vector<gpu::BvhWideNode> nodes;  // node 0 is the root
  BvhWideStats stats;
};

// Collapses `binary` and moves its leaves into the wide tree's leaf order (binary.triangleOrder and its leaf
// nodes' leftOrFirst change; its shape, boxes and SAH cost do not). Throws std::runtime_error when the tree
// would be deeper than the traversal stack (RL_BVH_STACK); a binary tree within that depth never is (a wide
// level is at least one binary level). `threads`: 0 for the hardware's (fewer for small trees); the result is
// the same for every count (the tests compare them).
BvhWide collapseBvh(Bvh& binary, uint32_t threads = 0, WideCollapse how = Settings{}.wideCollapse);

// A child box as the traversal decodes it (origin + q * 2^e, in float): tests use this.
struct WideChildBox {
  glm::vec3 min, max;
};
WideChildBox decodeChildBox(const gpu::BvhWideNode& node, uint32_t slot);
// What the traversal tests instead (the ray moved into the node's frame): each axis's power-of-two scale, and
// slot s's 8-bit planes as floats.
glm::vec3 wideScale(const gpu::BvhWideNode& node);
glm::vec3 wideLowPlanes(const gpu::BvhWideNode& node, uint32_t slot);
glm::vec3 wideHighPlanes(const gpu::BvhWideNode& node, uint32_t slot);
// Slot s's kind, the index of an interior slot's node, a leaf slot's meta byte and its triangle range.
enum class WideSlot { Empty, Interior, Leaf };
WideSlot slotKind(const gpu::BvhWideNode& node, uint32_t slot);
uint32_t slotChildIndex(const gpu::BvhWideNode& node, uint32_t slot);
inline uint32_t wideInteriorMask(const gpu::BvhWideNode& node) { return node.exponents >> 24; }
inline uint32_t wideMeta(const gpu::BvhWideNode& node, uint32_t slot) {
  return (node.meta[slot >> 2] >> ((slot & 3u) * 8u)) & 0xFFu;
}
// The triangle-mask bits of a leaf slot's meta byte (0 for 0: no leaf).
inline uint32_t wideLeafBits(uint32_t meta) {
  return meta == 0 ? 0u : ((2u << (meta >> 5)) - 1u) << (meta & 31u);
}
struct WideLeafRange {
  uint32_t first, count;  // BVH-order triangles
};
WideLeafRange wideLeafRange(const gpu::BvhWideNode& node, uint32_t slot);

}  // namespace raylab
