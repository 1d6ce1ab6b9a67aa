#include "renderer/bvh/bvh_presplit.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

namespace raylab {
namespace {

float surfaceArea(float dx, float dy, float dz) { return 2.0f * (dx * dy + dy * dz + dz * dx); }
float surfaceArea(const RTCBuildPrimitive& p) {
  return surfaceArea(p.upper_x - p.lower_x, p.upper_y - p.lower_y, p.upper_z - p.lower_z);
}

}  // namespace

// Embree's spatial-split callback (bvh_presplit.h): the boxes of the parts of a triangle on either side of the plane
// `dimension` = `position`, each cut down to the box the reference has already (it may be a part of a part).
// The triangle's corners on a side and its edges' crossings of the plane bound that side's part. Where float
// rounding leaves a side's box empty (a crossing just outside the reference's box), that side keeps the
// reference's box cut at the plane: a looser box loses no hit, an empty one would.
void splitTriangleReference(const RTCBuildPrimitive* prim, unsigned int dimension, float position, RTCBounds* leftBounds,
                            RTCBounds* rightBounds, void* userPtr) {
  const Triangle& t = (*static_cast<const std::vector<Triangle>*>(userPtr))[prim->primID];
  glm::vec3 lo[2] = {glm::vec3(std::numeric_limits<float>::max()), glm::vec3(std::numeric_limits<float>::max())};
  glm::vec3 hi[2] = {glm::vec3(-std::numeric_limits<float>::max()), glm::vec3(-std::numeric_limits<float>::max())};
  auto grow = [&](int side, glm::vec3 p) { lo[side] = glm::min(lo[side], p), hi[side] = glm::max(hi[side], p); };
  for (int i = 0; i < 3; ++i) {
    const glm::vec3 a = t.v[i], b = t.v[(i + 1) % 3];
    if (a[dimension] <= position) grow(0, a);
    if (a[dimension] >= position) grow(1, a);
    if ((a[dimension] < position && position < b[dimension]) || (b[dimension] < position && position < a[dimension])) {
      glm::vec3 c = a + (b - a) * ((position - a[dimension]) / (b[dimension] - a[dimension]));
      c[dimension] = position;
      grow(0, c);
      grow(1, c);
    }
  }
  const glm::vec3 primLo(prim->lower_x, prim->lower_y, prim->lower_z), primHi(prim->upper_x, prim->upper_y, prim->upper_z);
  RTCBounds* out[2] = {leftBounds, rightBounds};
  for (int side = 0; side < 2; ++side) {
    glm::vec3 cutLo = primLo, cutHi = primHi;
    (side == 0 ? cutHi : cutLo)[dimension] = position;
    glm::vec3 l = glm::max(lo[side], cutLo), h = glm::min(hi[side], cutHi);
    if (l.x > h.x || l.y > h.y || l.z > h.z) l = cutLo, h = cutHi;
    out[side]->lower_x = l.x, out[side]->lower_y = l.y, out[side]->lower_z = l.z;
    out[side]->upper_x = h.x, out[side]->upper_y = h.y, out[side]->upper_z = h.z;
  }
}

float presplitPriority(const RTCBuildPrimitive& reference, const Triangle& t) {
  const glm::vec3 lo = glm::min(t.v[0], glm::min(t.v[1], t.v[2])), hi = glm::max(t.v[0], glm::max(t.v[1], t.v[2]));
  const glm::vec3 extent = hi - lo;
  const float triangleBox = surfaceArea(extent.x, extent.y, extent.z);
  const float box = surfaceArea(reference);
  if (!(triangleBox > 0.0f)) return 0.0f;  // a degenerate triangle: nothing to gain
  // An axis-aligned triangle (up to float noise) is never cut: with the other half of its quad it fills its flat
  // box, and cutting the temple's four ground triangles alone (7 cuts) cost the hall's bounce rays 9% more
  // steps per warp efficiency (docs/results/lavapipe-presplit-rules).
  if (glm::min(extent.x, glm::min(extent.y, extent.z)) <= kPresplitFlatness * glm::max(extent.x, glm::max(extent.y, extent.z)))
    return 0.0f;
  const float area = 0.5f * glm::length(glm::cross(t.v[1] - t.v[0], t.v[2] - t.v[0]));
  return box - 2.0f * area * box / triangleBox;
}

size_t presplitReferences(RTCBuildPrimitive* prims, size_t count, size_t cuts, const std::vector<Triangle>& triangles) {
  if (cuts == 0) return count;  // the default: no pass over the references at all
  // Largest priority first; of equal ones the lower index (the comparison's second member, negated).
  using Item = std::pair<float, long long>;
  auto item = [&](size_t i) { return Item{presplitPriority(prims[i], triangles[prims[i].primID]), -static_cast<long long>(i)}; };
  // Only the `cuts` first references in that order can be cut: each cut takes the largest and leaves two pieces
  // below it, so a reference past them would be reached only after `cuts` cuts. Selecting them (linear) instead
  // of heaping all (n log n) keeps a 10M-triangle scene's presplit to a pass over its references.
  std::vector<Item> first;
  for (size_t i = 0; i < count; ++i)
    if (const Item it = item(i); it.first > 0.0f) first.push_back(it);
  if (first.size() > cuts) {
    std::nth_element(first.begin(), first.begin() + static_cast<std::ptrdiff_t>(cuts), first.end(), std::greater<Item>());
    first.resize(cuts);
  }
  std::priority_queue<Item> heap(std::less<Item>(), std::move(first));
  auto push = [&](size_t i) { heap.push(item(i)); };
  auto* userPtr = const_cast<std::vector<Triangle>*>(&triangles);  // read only, as in Embree's callback
  for (size_t made = 0; made < cuts && !heap.empty() && heap.top().first > 0.0f; ++made) {
    const size_t i = static_cast<size_t>(-heap.top().second);
    heap.pop();
    RTCBuildPrimitive& p = prims[i];
    const float extent[3] = {p.upper_x - p.lower_x, p.upper_y - p.lower_y, p.upper_z - p.lower_z};
    const unsigned axis = extent[0] >= extent[1] && extent[0] >= extent[2] ? 0u : extent[1] >= extent[2] ? 1u : 2u;
    const float lower[3] = {p.lower_x, p.lower_y, p.lower_z};
    RTCBounds left, right;
    splitTriangleReference(&p, axis, lower[axis] + 0.5f * extent[axis], &left, &right, userPtr);
    RTCBuildPrimitive other = p;
    p.lower_x = left.lower_x, p.lower_y = left.lower_y, p.lower_z = left.lower_z;
    p.upper_x = left.upper_x, p.upper_y = left.upper_y, p.upper_z = left.upper_z;
    other.lower_x = right.lower_x, other.lower_y = right.lower_y, other.lower_z = right.lower_z;
    other.upper_x = right.upper_x, other.upper_y = right.upper_y, other.upper_z = right.upper_z;
    prims[count] = other;
    push(i);
    push(count);
    ++count;
  }
  return count;
}

}  // namespace raylab
