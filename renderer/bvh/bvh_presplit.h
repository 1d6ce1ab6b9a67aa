// Presplitting before the spatial-split build (early split clipping: Ernst and Greiner, RT 2007; the pre-splits
// of Karras and Aila, HPG 2013): the references whose boxes hold the most empty space are cut in half, at the
// middle of the box's longest axis, before Embree sees them, so a long diagonal triangle enters the build as
// several tighter boxes. Embree's own spatial splits only cut where a node's SAH gains; these cuts happen
// everywhere such a triangle is, near the root included. Axis-aligned triangles are never cut (kPresplitFlatness).
// With 0.1% of the triangles cut, Sponza's rays take 16.7% / 11.1% / 7.6% fewer steps per warp efficiency (camera /
// bounce / shadow), the temple's views and the clutter room's as many as without cuts (within 0.3%), the
// temple-detail hall's about 1% more, the Cornell box's 2-4% more: its rotated boxes' faces are cut, planar quads
// like Sponza's leaning walls, which pay (lavapipe, docs/results/lavapipe-presplit-rules). Cutting by box area alone,
// the ground included, the H200 traced the hall's bounce rays 8% slower (docs/results/h200-tree-variants).
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

// A triangle whose box is thinner than this share of its longest side lies in an axis plane (up to float noise and
// modelling tolerance) and is never cut. On lavapipe's count (docs/results/lavapipe-presplit-rules) every
// threshold from 1e-5 to 3e-4 gives Sponza the same tree; 3e-3 leaves out the slightly leaning walls whose
// cuts make Sponza's gain.
inline constexpr float kPresplitFlatness = 1e-4f;

// A reference's empty space, the order of the cuts: its box's surface area less the part of it the triangle
// covers, estimated as twice the triangle's area scaled by this box's share of the whole triangle's box area.
// Zero for a degenerate or an axis-aligned triangle (kPresplitFlatness), which is never cut; a flat triangle fills
// at most half its box's area.
float presplitPriority(const RTCBuildPrimitive& reference, const Triangle& triangle);

// Makes up to `cuts` cuts among prims[0, count) (primID: the triangle's index in `triangles`), the largest
// priority first, each piece kept in the heap for further cuts; a cut replaces a reference by one piece and
// appends the other at the end. `prims` must have room for count + cuts. Returns the new count. The same input
// gives the same references in the same order (ties go to the lower index).
size_t presplitReferences(RTCBuildPrimitive* prims, size_t count, size_t cuts, const std::vector<Triangle>& triangles);

}  // namespace raylab
