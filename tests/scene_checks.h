// Checks of procedural geometry shared by the scene tests: a brute-force CPU ray caster, closed,
// outward-wound solids and byte-exact comparison of two builds.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <random>
#include <tuple>
#include <utility>
#include <vector>

#include "scenes/scene.h"

namespace raylab {

// `count` triangles with vertices uniform in [-10, 10)^3 from an mt19937 seeded with `seed`: a soup with no
// structure for the BVH builders to exploit.
inline std::vector<Triangle> randomTriangles(size_t count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-10.0f, 10.0f);
  std::vector<Triangle> tris(count);
  for (Triangle& t : tris)
    for (glm::vec3& v : t.v) v = {u(rng), u(rng), u(rng)};
  return tris;
}

inline constexpr float kMiss = std::numeric_limits<float>::infinity();

struct Hit {
  float t = kMiss;
  size_t triangle = 0;
};

// Möller-Trumbore, both faces; the nearest hit (t = kMiss for none).
inline Hit nearestHit(const Scene& s, const glm::vec3& o, const glm::vec3& d) {
  Hit best;
  for (size_t i = 0; i < s.triangles.size(); ++i) {
    const Triangle& t = s.triangles[i];
    glm::vec3 e1 = t.v[1] - t.v[0], e2 = t.v[2] - t.v[0], p = glm::cross(d, e2);
    float det = glm::dot(e1, p);
    if (std::fabs(det) < 1e-12f) continue;
    float inv = 1.0f / det;
    glm::vec3 q = o - t.v[0];
    float u = glm::dot(q, p) * inv;
    if (u < 0.0f || u > 1.0f) continue;
    glm::vec3 r = glm::cross(q, e1);
    float v = glm::dot(d, r) * inv;
    if (v < 0.0f || u + v > 1.0f) continue;
    float dist = glm::dot(e2, r) * inv;
    if (dist > 1e-4f && dist < best.t) best = {dist, i};
  }
  return best;
}

inline float castRay(const Scene& s, const glm::vec3& o, const glm::vec3& d) { return nearestHit(s, o, d).t; }

// Primary ray directions of a pinhole camera (the lab's benchmark aspect is 2:1).
inline std::vector<glm::vec3> cameraRays(const Viewpoint& v, int width, int height) {
  glm::vec3 f = glm::normalize(v.target - v.position);
  glm::vec3 r = glm::normalize(glm::cross(f, v.up));
  glm::vec3 u = glm::cross(r, f);
  float h = std::tan(0.5f * v.yfovRadians), aspect = static_cast<float>(width) / static_cast<float>(height);
  std::vector<glm::vec3> rays;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      float sx = (2.0f * (static_cast<float>(x) + 0.5f) / static_cast<float>(width) - 1.0f) * h * aspect;
      float sy = (1.0f - 2.0f * (static_cast<float>(y) + 0.5f) / static_cast<float>(height)) * h;
      rays.push_back(glm::normalize(f + sx * r + sy * u));
    }
  return rays;
}

// For a union of closed, consistently wound solids, every directed edge a->b is matched by b->a
// exactly as often: a crack, a missing face or a flipped triangle breaks this.
inline void expectEdgesPaired(const Scene& s) {
  using Key = std::tuple<float, float, float>;
  std::map<std::pair<Key, Key>, int> balance;
  auto key = [](const glm::vec3& v) { return Key{v.x, v.y, v.z}; };
  for (const Triangle& t : s.triangles)
    for (int i = 0; i < 3; ++i) {
      Key a = key(t.v[i]), b = key(t.v[(i + 1) % 3]);
      if (a < b)
        ++balance[{a, b}];
      else
        --balance[{b, a}];
    }
  int unpaired = 0;
  for (const auto& [edge, count] : balance) unpaired += count != 0;
  EXPECT_EQ(unpaired, 0);
}

inline float signedVolume(const Scene& s) {
  double v = 0.0;
  for (const Triangle& t : s.triangles) v += glm::dot(t.v[0], glm::cross(t.v[1], t.v[2])) / 6.0;
  return static_cast<float>(v);
}

// The triangles as raw bytes: two builds are the same scene exactly when these are equal.
inline std::vector<unsigned char> triangleBytes(const Scene& s) {
  std::vector<unsigned char> b(s.triangles.size() * sizeof(Triangle));
  if (!b.empty()) std::memcpy(b.data(), s.triangles.data(), b.size());
  return b;
}

}  // namespace raylab
