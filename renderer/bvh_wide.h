// The compressed 8-wide BVH (shaders/shared_types.h: BvhWideNode) made by collapsing a binary Bvh, whoever
// built it: each wide node takes up to 8 subtrees of the binary tree (opening the largest-area interior child
// until 8 or only leaves remain), quantizes their boxes outwards and places them in direction slots. Leaves are
// the binary tree's leaves, referenced by triangle range: the BVH triangle order (GpuTriangle, emitters, the rt
// tracer's structure) is the binary tree's, unchanged.
#pragma once

#include <cstdint>
#include <vector>

#include "renderer/bvh.h"
#include "shaders/shared_types.h"

namespace raylab {

struct BvhWideStats {
  uint32_t nodeCount = 0;
  uint32_t leafCount = 0;
  uint32_t maxDepth = 0;  // root = 0; the traversal stack holds at most maxDepth + 1 groups
  double buildMs = 0.0;   // the collapse only
  // Bytes of the tree itself (nodes and leaf records), without the triangles.
  uint64_t treeBytes() const { return uint64_t(nodeCount) * sizeof(gpu::BvhWideNode) + uint64_t(leafCount) * sizeof(gpu::BvhWideLeaf); }
};

struct BvhWide {
  std::vector<gpu::BvhWideNode> nodes;  // node 0 is the root
  std::vector<gpu::BvhWideLeaf> leaves;
  BvhWideStats stats;
};

// Throws std::runtime_error when the tree would be deeper than the traversal stack (RL_BVH_STACK); a binary
// tree within that depth never is (a wide level is at least one binary level).
BvhWide collapseBvh(const Bvh& binary);

// A child box as the traversal decodes it (origin + q * 2^e, in float): tests and the CPU twin use this.
struct WideChildBox {
  glm::vec3 min, max;
};
WideChildBox decodeChildBox(const gpu::BvhWideNode& node, uint32_t slot);
// What the traversal tests instead (the ray moved into the node's frame): each axis's power-of-two scale, and
// slot s's 8-bit planes as floats.
glm::vec3 wideScale(const gpu::BvhWideNode& node);
glm::vec3 wideLowPlanes(const gpu::BvhWideNode& node, uint32_t slot);
glm::vec3 wideHighPlanes(const gpu::BvhWideNode& node, uint32_t slot);
// Slot s's kind: 0 empty, 1 interior, 2 leaf; and its index (wide node or leaf record).
enum class WideSlot { Empty, Interior, Leaf };
WideSlot slotKind(const gpu::BvhWideNode& node, uint32_t slot);
uint32_t slotChildIndex(const gpu::BvhWideNode& node, uint32_t slot);

}  // namespace raylab
