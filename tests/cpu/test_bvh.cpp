// Structural checks of the BVH builder: every triangle in exactly one leaf, children inside parents,
// depth within the shaders' traversal stack, and degenerate inputs handled.
#include <gtest/gtest.h>

#include <random>

#include "renderer/bvh.h"
#include "scenes/procedural.h"

namespace raylab {
namespace {

bool contains(const gpu::BvhNode& outer, const glm::vec3& p) {
  return glm::all(glm::greaterThanEqual(p, outer.boundsMin)) && glm::all(glm::lessThanEqual(p, outer.boundsMax));
}

void checkBvh(const std::vector<Triangle>& tris, const Bvh& bvh) {
  std::vector<int> seen(tris.size(), 0);
  ASSERT_EQ(bvh.triangleOrder.size(), tris.size());
  std::vector<std::pair<uint32_t, uint32_t>> stack{{0u, 0u}};
  uint32_t maxDepth = 0;
  while (!stack.empty()) {
    auto [index, depth] = stack.back();
    stack.pop_back();
    maxDepth = std::max(maxDepth, depth);
    const gpu::BvhNode& n = bvh.nodes.at(index);
    if (n.triCount > 0) {
      for (uint32_t i = n.leftOrFirst; i < n.leftOrFirst + n.triCount; ++i) {
        uint32_t t = bvh.triangleOrder.at(i);
        seen.at(t)++;
        for (const glm::vec3& v : tris[t].v) EXPECT_TRUE(contains(n, v));
      }
      continue;
    }
    for (uint32_t c = n.leftOrFirst; c < n.leftOrFirst + 2; ++c) {
      const gpu::BvhNode& child = bvh.nodes.at(c);
      EXPECT_TRUE(contains(n, child.boundsMin) && contains(n, child.boundsMax));
      stack.push_back({c, depth + 1});
    }
  }
  for (size_t t = 0; t < seen.size(); ++t) ASSERT_EQ(seen[t], 1) << "triangle " << t;
  EXPECT_LT(maxDepth, uint32_t(RL_BVH_STACK));
  EXPECT_EQ(bvh.stats.nodeCount, bvh.nodes.size());
}

TEST(Bvh, TempleIsWellFormed) {
  Scene temple = makeTemple();
  Bvh bvh = buildBvh(temple.triangles);
  checkBvh(temple.triangles, bvh);
  EXPECT_GT(bvh.stats.leafCount, temple.triangles.size() / 8);
}

TEST(Bvh, RandomTrianglesAndIdenticalTriangles) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-10.0f, 10.0f);
  std::vector<Triangle> tris(3000);
  for (Triangle& t : tris)
    for (glm::vec3& v : t.v) v = {u(rng), u(rng), u(rng)};
  checkBvh(tris, buildBvh(tris));
  // Many triangles at the same place cannot be split by SAH; the builder must still terminate and
  // stay within the stack depth.
  std::vector<Triangle> same(500, tris[0]);
  checkBvh(same, buildBvh(same));
}

TEST(Bvh, SingleTriangle) {
  std::vector<Triangle> one(1);
  one[0].v[1] = {1, 0, 0};
  one[0].v[2] = {0, 1, 0};
  Bvh bvh = buildBvh(one);
  checkBvh(one, bvh);
  EXPECT_EQ(bvh.nodes.size(), 1u);
}

}  // namespace
}  // namespace raylab
