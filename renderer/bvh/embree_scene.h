// The scene's triangles in an Embree scene: the CPU reference for closest hits and shadow rays that the GPU
// traversal is checked against (tests/gpu/bvh/test_embree_hits.cpp). Robust mode (RTC_SCENE_FLAG_ROBUST): no
// arithmetic shortcuts that could miss a hit on an edge, since this is the reference.
#pragma once

#include <vector>

#include "renderer/bvh/embree_device.h"
#include "scenes/scene.h"

namespace raylab {

struct EmbreeHit {
  float t = -1.0f;         // negative: no hit
  uint32_t triangle = 0;   // index into the triangles the scene was made of
  glm::vec2 bary{0.0f};    // Embree's u, v: the hit is (1-u-v) v0 + u v1 + v v2
  glm::vec3 normal{0.0f};  // geometric normal, unnormalized (Embree's Ng)
};

class EmbreeScene {
 public:
  explicit EmbreeScene(const std::vector<Triangle>& triangles);  // throws std::runtime_error on failure
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  // Hits with t in (tNear, tMax), open at both ends and both faces counting, as in our shaders.
  EmbreeHit intersect(const glm::vec3& origin, const glm::vec3& direction, float tMax = 1e30f,
                      float tNear = 0.0f) const;
  // Whether anything lies in (tNear, tMax).
  bool occluded(const glm::vec3& origin, const glm::vec3& direction, float tMax, float tNear = 0.0f) const;

 private:
  EmbreeDevice device_;
  RTCScene scene_ = nullptr;
};

}  // namespace raylab
