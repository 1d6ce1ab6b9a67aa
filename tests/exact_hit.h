// The tests' closest hit by brute force in double precision (Moeller-Trumbore over every triangle, both
// faces, t > 0): the reference for the oracle key's hit distances and for Embree's hits.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/scene.h"

namespace raylab::test {

struct ExactHit {
  double t = -1.0;  // negative: no hit
  uint32_t triangle = 0;
};

// `minDeterminant`: triangles seen this close to edge-on are skipped.
inline ExactHit exactClosestHit(const std::vector<Triangle>& tris, glm::dvec3 o, glm::dvec3 d, double minDeterminant) {
  ExactHit best;
  for (uint32_t i = 0; i < tris.size(); ++i) {
    const Triangle& t = tris[i];
    glm::dvec3 e1 = glm::dvec3(t.v[1]) - glm::dvec3(t.v[0]), e2 = glm::dvec3(t.v[2]) - glm::dvec3(t.v[0]);
    glm::dvec3 p = glm::cross(d, e2);
    double det = glm::dot(e1, p);
    if (std::abs(det) < minDeterminant) continue;
    glm::dvec3 s = o - glm::dvec3(t.v[0]);
    double u = glm::dot(s, p) / det;
    glm::dvec3 q = glm::cross(s, e1);
    double v = glm::dot(d, q) / det;
    double dist = glm::dot(e2, q) / det;
    if (u >= 0 && v >= 0 && u + v <= 1 && dist > 0 && (best.t < 0 || dist < best.t)) best = {dist, i};
  }
  return best;
}

}  // namespace raylab::test
