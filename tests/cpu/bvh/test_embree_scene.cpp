// The CPU hit reference (renderer/bvh/embree_scene.h) checked itself: Embree's closest hit and shadow-ray answer
// against a brute-force double-precision intersection of every triangle, on the temple with random rays.
// The GPU traversal is then checked against Embree (tests/gpu/bvh/test_embree_hits.cpp), where brute force
// over Sponza's 262k triangles would be too slow.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "renderer/bvh/embree_scene.h"
#include "scenes/procedural.h"
#include "tests/exact_hit.h"

namespace raylab {
namespace {

using test::ExactHit;
ExactHit exactClosestHit(const std::vector<Triangle>& tris, glm::dvec3 o, glm::dvec3 d) {
  return test::exactClosestHit(tris, o, d, 1e-15);
}

TEST(EmbreeScene, ClosestHitsAndShadowRaysEqualBruteForceOnTheTemple) {
  Scene temple = makeTemple();
  EmbreeScene embree(temple.triangles);
  Bounds b = temple.bounds();
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::normal_distribution<float> gauss;
  uint32_t rays = 0, hits = 0, sameTriangle = 0, tMismatch = 0, shadowMismatch = 0;
  for (int i = 0; i < 3000; ++i) {
    glm::vec3 o = b.min + glm::vec3(unit(rng), unit(rng), unit(rng)) * b.extent();
    glm::vec3 d = glm::normalize(glm::vec3(gauss(rng), gauss(rng), gauss(rng)));
    ExactHit ref = exactClosestHit(temple.triangles, o, d);
    EmbreeHit hit = embree.intersect(o, d);
    ++rays;
    if (ref.t < 1e-4) continue;  // a miss, or an origin on a surface: either answer is right
    ++hits;
    if (std::abs(hit.t - ref.t) > 1e-4 * (1.0 + ref.t)) ++tMismatch;
    sameTriangle += hit.triangle == ref.triangle;
    // A shadow ray to a point before the hit is free, one past it is blocked.
    shadowMismatch += embree.occluded(o, d, static_cast<float>(0.99 * ref.t));
    shadowMismatch += !embree.occluded(o, d, static_cast<float>(1.01 * ref.t));
  }
  EXPECT_GT(hits, rays / 2);
  EXPECT_EQ(tMismatch, 0u);
  EXPECT_EQ(shadowMismatch, 0u);
  // Two triangles can share the hit point (an edge, coplanar faces): the triangle may differ there only.
  EXPECT_GE(sameTriangle, hits * 99 / 100);
}

TEST(EmbreeScene, EmptySceneAndTMaxAreHonoured) {
  EmbreeScene empty({});
  EXPECT_LT(empty.intersect({0, 0, 0}, {0, 0, 1}).t, 0.0f);
  EXPECT_FALSE(empty.occluded({0, 0, 0}, {0, 0, 1}, 1e30f));
  std::vector<Triangle> one(1);
  one[0].v[0] = {-1, -1, 2};
  one[0].v[1] = {1, -1, 2};
  one[0].v[2] = {0, 1, 2};
  EmbreeScene scene(one);
  EmbreeHit hit = scene.intersect({0, 0, 0}, {0, 0, 1});
  EXPECT_NEAR(hit.t, 2.0f, 1e-6f);
  EXPECT_EQ(hit.triangle, 0u);
  EXPECT_LT(scene.intersect({0, 0, 0}, {0, 0, 1}, 1.5f).t, 0.0f);   // beyond tMax
  EXPECT_LT(scene.intersect({0, 0, 0}, {0, 0, -1}).t, 0.0f);        // behind the origin
  EXPECT_NEAR(scene.intersect({0, 0, 4}, {0, 0, -1}).t, 2.0f, 1e-6f);  // the back face counts
  EXPECT_TRUE(scene.occluded({0, 0, 0}, {0, 0, 1}, 3.0f));
  EXPECT_FALSE(scene.occluded({0, 0, 0}, {0, 0, 1}, 1.0f));
  // The segment is open at both ends, as the shaders' test (t > 0, t < tMax): a ray starting on the triangle,
  // leaving it or running in its plane, does not hit it at t = 0, and a shadow ray ending on it is not blocked.
  EXPECT_LT(scene.intersect({0, 0, 2}, {0, 0, 1}).t, 0.0f);
  EXPECT_LT(scene.intersect({0, 0, 2}, {0, 0, -1}).t, 0.0f);
  EXPECT_FALSE(scene.occluded({0, 0, 2}, {0, 0, 1}, 1e30f));
  EXPECT_FALSE(scene.occluded({0, 0, 0}, {0, 0, 1}, 2.0f));
}

}  // namespace
}  // namespace raylab
