#include "renderer/bvh/bvh_sah.h"

namespace raylab {
namespace {

double nodeSurfaceArea(const gpu::BvhNode& n) {
  glm::dvec3 e = glm::dvec3(n.boundsMax) - glm::dvec3(n.boundsMin);
  if (e.x < 0.0 || e.y < 0.0 || e.z < 0.0) return 0.0;  // the empty tree's inverted boxes
  return 2.0 * (e.x * e.y + e.y * e.z + e.z * e.x);
}

}  // namespace

double bvhSahCost(const Bvh& bvh, double traversalCost, double intersectionCost) {
  if (bvh.nodes.empty() || bvh.triangleOrder.empty()) return 0.0;
  double rootArea = nodeSurfaceArea(bvh.nodes[0]);
  // Walk from the root rather than over the array: only reachable nodes count.
  std::vector<uint32_t> stack{0u};
  double sum = 0.0;
  while (!stack.empty()) {
    const gpu::BvhNode& n = bvh.nodes[stack.back()];
    stack.pop_back();
    double area = nodeSurfaceArea(n);
    if (n.triCount > 0) {
      sum += area * n.triCount * intersectionCost;
    } else {
      sum += area * traversalCost;
      stack.push_back(n.leftOrFirst);
      stack.push_back(n.leftOrFirst + 1);
    }
  }
  // A flat root (one planar triangle) has no area: its one leaf then costs its triangle count.
  if (!(rootArea > 0.0)) return bvh.nodes[0].triCount > 0 ? bvh.nodes[0].triCount * intersectionCost : 0.0;
  return sum / rootArea;
}

}  // namespace raylab
