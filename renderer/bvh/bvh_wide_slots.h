// Which binary subtrees become the slots of each wide node (renderer/bvh/bvh_wide.h), by either collapse
// (Settings::wideCollapse):
// - greedy (bvh_wide_greedy.cpp): open the largest-area interior child until 8 subtrees or only leaves remain,
//   within the node's leaf budget; each binary leaf is a leaf slot (one per 8 triangles).
// - SAH (bvh_wide_sah.cpp; Ylitie, Karras and Laine, HPG 2017, section 3.1): bottom up, for every binary node n
//   and i = 1..8, the cheapest way to represent n's subtree as at most i slots of a wide parent, each slot a
//   wide node of its own (an interior slot), a leaf group (all the triangles under a binary node, at most 8, one
//   slot; a binary leaf of more takes one slot per 8), or the subtree shared between n's two children's slots.
//   Top down, each wide node takes the choices that led to its cheapest cost. The cost is CWBVH's SAH:
//   area(wide node) * nodeCost + area(leaf slot) * triangles * triangleCost, over all nodes and leaf slots.
#pragma once

#include <cstdint>
#include <vector>

#include "renderer/bvh/bvh.h"
#include "renderer/settings/settings.h"

namespace raylab {

struct BvhWide;

// Ylitie et al.'s weights: one triangle test is about 0.3 of one wide node's eight box tests. (On the H200,
// 1.0 gave the same frames within 1%, docs/results/h200-wide-bvh/sah-collapse.)
constexpr float kWideNodeCost = 1.0f;
constexpr float kWideTriangleCost = 0.3f;

// Half the surface area of a box (0 for an inverted one): the SAH's weights, and greedy's order of opening.
inline float boxHalfArea(glm::vec3 lo, glm::vec3 hi) {
  const glm::vec3 d = glm::max(hi - lo, glm::vec3(0.0f));
  return d.x * d.y + d.y * d.z + d.z * d.x;
}
inline float boxHalfArea(const gpu::BvhNode& n) { return boxHalfArea(n.boundsMin, n.boundsMax); }

// One slot's content: binary node `binary` as an interior slot (a wide node of its own) or as a leaf group.
struct WideSlotChoice {
  uint32_t binary;
  bool leaf;
};

class WideSlotChooser {
 public:
  // Everything the choices need, subtrees on `threads` threads (the same for every count). An empty tree (the
  // root's box inverted) has no slots.
  WideSlotChooser(const Bvh& binary, WideCollapse how, uint32_t threads);

  // The slots of the wide node made from binary node `index`, in the order of the binary tree's leaves: at most
  // 8 once leaf groups of more than 8 triangles count one slot per 8, their leaf groups 32 triangles in all.
  std::vector<WideSlotChoice> slotsOf(uint32_t index) const;

  // The triangles under binary node `index`.
  uint32_t trianglesUnder(uint32_t index) const { return triangles_[index]; }

 private:
  void solve(uint32_t index);
  std::vector<WideSlotChoice> greedySlotsOf(uint32_t index) const;
  std::vector<WideSlotChoice> sahSlotsOf(uint32_t index) const;
  void expand(uint32_t index, uint32_t slots, std::vector<WideSlotChoice>& out) const;
  void expandSplit(uint32_t index, uint32_t slots, std::vector<WideSlotChoice>& out) const;
  float cost(uint32_t index, uint32_t slots) const { return cost_[size_t(index) * 8 + slots - 1]; }

  const Bvh& binary_;
  WideCollapse how_;
  std::vector<uint32_t> triangles_;  // 0: not solved yet (every subtree of a non-empty tree has a triangle)
  // SAH only:
  std::vector<float> cost_;      // [node * 8 + i - 1]: at most i slots
  std::vector<uint8_t> choice_;  // the same index: kLeaf, kInterior or kSplit | slots shared by the children
};

// The SAH cost of a built wide tree with the weights above, from its quantized boxes (what the traversal
// tests), divided by the area of the binary tree's root box: comparable across collapses of one binary tree.
double wideSahCost(const BvhWide& wide, const Bvh& binary);

}  // namespace raylab
