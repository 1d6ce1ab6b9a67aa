// Inside the wide collapse (renderer/bvh/bvh_wide.h): one wide node decided from the binary subtree under it,
// before it has a place. Everything of the node but where its children and triangles go is a function of that
// subtree alone, so renderer/bvh/bvh_wide_collapse.cpp can plan subtrees on several threads and place them after.
#pragma once

#include <cstdint>
#include <vector>

#include "renderer/bvh/bvh.h"
#include "renderer/bvh/bvh_wide_slots.h"
#include "shaders/shared_types.h"

namespace raylab {

struct WideNodePlan {
  gpu::BvhWideNode node{};  // all but childBase and triBase, which depend on the node's place
  bool empty = false;       // no children (the empty scene's root): stored as it is, all zeros
  uint32_t blockStart = 0;  // the leaf block's first triangle-mask bit: 1 when every leaf is one triangle
  uint32_t leafSlots = 0;
  std::vector<uint32_t> leaves;     // binary leaves, in their order in the node's leaf block
  std::vector<uint32_t> interiors;  // the binary nodes of the interior slots, in slot order: the wide nodes
                                    // childBase, childBase + 1, ...
};

// The wide node for binary node `binaryIndex`: the slots `slots` chose for it (bvh_wide_slots.h), their direction
// slots, quantized boxes and leaf meta bytes.
WideNodePlan planWideNode(const Bvh& binary, const WideSlotChooser& slots, uint32_t binaryIndex);

}  // namespace raylab
