// Insertion-based optimization of a built binary BVH (Bittner, Hapala and Havran, "Fast Insertion-Based
// Optimization of Bounding Volume Hierarchies", CGF 2013, section 3.4): the interior nodes whose box is largest
// against their children's are taken out with their parent, and their two children are put back, each as the
// new sibling of the node where it adds the least surface area to the tree (a branch-and-bound search from the
// root). Leaves keep their triangles and boxes; only the interior boxes and the shape change, so the tree's
// SAH (bvh_sah.h) falls or stays: a move is kept only if it lowered the interior nodes' total area, and the
// whole optimization only if the deepest leaf stays within kMaxBvhDepth, buildBvh's limit.
//
// Why: on Sponza's rays (tracebench --export, 2048x1024) Embree's spatial-split tree takes 44.4 steps a first-
// bounce ray where tinybvh's SBVH takes 38.2, with the same leaf visits (2.6-2.7 a ray): the gap is interior
// nodes, which this pass rearranges (docs/results/lavapipe-tree-steps).
#pragma once

#include <cstdint>

#include "renderer/bvh/bvh.h"

namespace raylab {

struct ReinsertStats {
  uint32_t passes = 0;        // passes run (each a batch of the worst nodes; the last moved none, or the limit)
  uint32_t kept = 0;          // passes that moved at least one node (0: the tree is as it was)
  uint32_t reinserted = 0;    // moves kept: each lowered the interior area (the others were taken back)
  double areaBefore = 0.0;    // the interior nodes' total surface area over the root's, before and after
  double areaAfter = 0.0;
  double ms = 0.0;
};

// Optimizes `bvh` in place, at most `passes` passes of the worst `fraction` of the interior nodes; the nodes are
// laid out again depth first, each pair of siblings adjacent, and the leaves' entries (triangleOrder) in the
// order the leaves come, so a consumer of the tree reads it as it reads buildBvh's. Updates bvh.stats (nodes,
// leaves, depth, SAH). A tree of fewer than four leaves is left as it is. Deterministic.
// Only the interior nodes' area moves (leaves keep theirs), so no cost weights are needed: any SAH weighting
// falls with the interior area.
ReinsertStats reinsertOptimize(Bvh& bvh, uint32_t passes, double fraction = 0.01);

}  // namespace raylab
