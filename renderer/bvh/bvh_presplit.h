// Presplitting before the spatial-split build (early split clipping: Ernst and Greiner, RT 2007; the pre-splits
// of Karras and Aila, HPG 2013): the references whose boxes hold the most empty space are cut in half, at the
// middle of the box's longest axis, before Embree sees them, so a long diagonal triangle enters the build as
// several tighter boxes. Embree's own spatial splits only cut where a node's SAH gains; these cuts happen
// everywhere such a triangle is, near the root included. With 0.1% of the triangles cut, Sponza's rays take 16%
// fewer steps a camera ray and 10% fewer a bounce ray, the temple hall's 3-7% more (docs/results/h200-tree-variants).
#pragma once

#include <cstddef>
#include <vector>

#include "renderer/bvh/embree_api.h"
#include "scenes/scene.h"

namespace raylab {

// The boxes of the parts of a reference's triangle (prim->primID in the std::vector<Triangle> at userPtr) on
// either side of the plane `dimension` = `position`, each within the reference's box: Embree's splitPrimitive
// callback for the spatial-split build (buildBvh), and the presplit's cut.
void splitTriangleReference(const RTCBuildPrimitive* prim, unsigned int dimension, float position,
                            RTCBounds* leftBounds, RTCBounds* rightBounds, void* userPtr);

// A reference's empty space, the order of the cuts: its box's surface area less the part of it the triangle
// covers, estimated as twice the triangle's area scaled by this box's share of the whole triangle's box area.
// Zero for a degenerate triangle, which is never cut; a flat triangle fills at most half its box's area.
float presplitPriority(const RTCBuildPrimitive& reference, const Triangle& triangle);

// Makes up to `cuts` cuts among prims[0, count) (primID: the triangle's index in `triangles`), the largest
// priority first, each piece kept in the heap for further cuts; a cut replaces a reference by one piece and
// appends the other at the end. `prims` must have room for count + cuts. Returns the new count. The same input
// gives the same references in the same order (ties go to the lower index).
size_t presplitReferences(RTCBuildPrimitive* prims, size_t count, size_t cuts, const std::vector<Triangle>& triangles);

}  // namespace raylab
