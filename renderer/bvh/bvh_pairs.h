// The binary BVH in the layout its GPU traversal reads (shaders/shared_types.h, BvhPairNode): every interior
// node as its two children's boxes, leaf children inline. Pair node 0 holds the root's children; interior nodes
// keep the binary tree's order among themselves, so a subtree stays as near in memory as before.
#pragma once

#include <vector>

#include "renderer/bvh/bvh.h"

namespace raylab {

// A root that is a leaf becomes one pair node with that leaf in both slots (its triangles are then tested
// twice, which finds the same hit); a tree without triangles (buildBvh's empty tree among them), one whose slots
// hold RL_BVH_NO_CHILD behind boxes no ray enters.
std::vector<gpu::BvhPairNode> pairNodes(const Bvh& bvh);

}  // namespace raylab
