// The surface-area-heuristic cost of a built BVH: the expected cost of one ray that hits the root's box,
// counted in node visits and triangle tests. Measures and compares builders (tests, the build report); the
// builder itself does not use it.
#pragma once

#include "renderer/bvh/bvh.h"

namespace raylab {

// Sum over interior nodes of area(node) * traversalCost, plus over leaves of area(leaf) * triangles *
// intersectionCost, divided by the root's area. With both costs 1 an interior visit costs one triangle test,
// the weighting our shaders' loop roughly has. 0 for an empty tree.
double bvhSahCost(const Bvh& bvh, double traversalCost = 1.0, double intersectionCost = 1.0);

}  // namespace raylab
