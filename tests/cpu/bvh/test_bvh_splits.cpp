// The binary BVH with spatial splits (BvhSplits::Spatial, Embree's high-quality build with our split callback)
// and its leaf records: every point of every triangle lies in the box of a leaf that holds it (a split that cut
// a part's box too tight would lose hits there), children inside parents, depth within the stack, and on long
// thin overlapping triangles (Sponza's kind) the splits happen and lower the SAH cost.
#include <gtest/gtest.h>

#include <random>
#include <stdexcept>
#include <vector>

#include "renderer/bvh/bvh.h"
#include "renderer/bvh/bvh_leaf_records.h"
#include "renderer/bvh/bvh_sah.h"
#include "scenes/procedural.h"
#include "tests/scene_checks.h"

namespace raylab {
namespace {

bool inside(const gpu::BvhNode& n, const glm::vec3& p, float slack = 0.0f) {
  return glm::all(glm::greaterThanEqual(p, n.boundsMin - slack)) && glm::all(glm::lessThanEqual(p, n.boundsMax + slack));
}

// Long thin planks (two triangles each) across a box along the three axes, like Sponza's long floor, wall and
// beam triangles: each overlaps many others' boxes, so no split of the list separates them well, and cutting
// them where they cross pays.
std::vector<Triangle> longPlanks(size_t planks, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-10.0f, 10.0f), w(0.05f, 0.3f), len(3.0f, 8.0f);
  std::vector<Triangle> tris;
  for (size_t i = 0; i < planks; ++i) {
    const int axis = int(i % 3), across = (axis + 1) % 3;
    glm::vec3 a{u(rng), u(rng), u(rng)};
    glm::vec3 b = a, c = a;
    b[axis] += len(rng);
    c[across] += w(rng);
    const glm::vec3 d = b + (c - a);
    tris.push_back(Triangle{{a, b, c}});
    tris.push_back(Triangle{{b, d, c}});
  }
  return tris;
}

struct SplitTreeWalk {
  const std::vector<Triangle>& tris;
  const Bvh& bvh;
  std::vector<std::vector<uint32_t>> leavesOf;  // triangle -> the leaves holding it
  uint32_t maxDepth = 0, leaves = 0;

  void walk(uint32_t index, uint32_t depth) {
    maxDepth = std::max(maxDepth, depth);
    const gpu::BvhNode& n = bvh.nodes.at(index);
    if (n.triCount > 0) {
      leaves++;
      for (uint32_t e = n.leftOrFirst; e < n.leftOrFirst + n.triCount; ++e) leavesOf.at(bvh.triangleOrder.at(e)).push_back(index);
      return;
    }
    for (uint32_t c = n.leftOrFirst; c < n.leftOrFirst + 2; ++c) {
      const gpu::BvhNode& child = bvh.nodes.at(c);
      EXPECT_TRUE(inside(n, child.boundsMin) && inside(n, child.boundsMax)) << "node " << c;
      walk(c, depth + 1);
    }
  }
};

// Points on the triangle (corners, edge points and inner points on a barycentric grid) must each lie in a box
// of a leaf that holds the triangle.
void expectCovered(const std::vector<Triangle>& tris, const Bvh& bvh) {
  SplitTreeWalk w{tris, bvh, std::vector<std::vector<uint32_t>>(tris.size())};
  w.walk(0, 0);
  EXPECT_LT(w.maxDepth, uint32_t(RL_BVH_STACK));
  EXPECT_EQ(bvh.nodes.size(), 2 * size_t(w.leaves) - 1);
  EXPECT_EQ(bvh.stats.references, bvh.triangleOrder.size());
  EXPECT_LE(bvh.triangleOrder.size(), tris.size() + size_t(kSpatialSplitBudget * tris.size()));
  constexpr int kGrid = 12;
  // The points are rounded where the boxes are not (a flat triangle's points leave its plane by an ulp or so):
  // a millionth of the scene's size is far below any real gap and far above the rounding.
  const float slack = 1e-6f * glm::length(bvh.nodes[0].boundsMax - bvh.nodes[0].boundsMin);
  size_t uncovered = 0;
  for (size_t t = 0; t < tris.size(); ++t) {
    ASSERT_FALSE(w.leavesOf[t].empty()) << "triangle " << t << " is in no leaf";
    for (int i = 0; i <= kGrid; ++i)
      for (int j = 0; i + j <= kGrid; ++j) {
        const float b1 = float(i) / kGrid, b2 = float(j) / kGrid;
        const glm::vec3 p = tris[t].v[0] * (1.0f - b1 - b2) + tris[t].v[1] * b1 + tris[t].v[2] * b2;
        bool found = false;
        for (uint32_t leaf : w.leavesOf[t]) found = found || inside(bvh.nodes[leaf], p, slack);
        if (!found && uncovered++ < 5) ADD_FAILURE() << "triangle " << t << " point (" << b1 << ", " << b2 << ") in no leaf box";
      }
  }
  EXPECT_EQ(uncovered, 0u);
}

TEST(BvhSplits, PlanksAreSplitCoveredAndCheaper) {
  const std::vector<Triangle> tris = longPlanks(1500, 7);
  const Bvh plain = buildBvh(tris);
  const Bvh split = buildBvh(tris, kDefaultMaxLeafSize, 0, BvhSplits::Spatial);
  expectCovered(tris, split);
  EXPECT_GT(split.stats.references, tris.size()) << "no triangle was split";
  EXPECT_EQ(plain.stats.references, tris.size());
  EXPECT_LT(split.stats.sahCost, 0.95 * plain.stats.sahCost);
  RecordProperty("sah_plain", std::to_string(plain.stats.sahCost));
  RecordProperty("sah_split", std::to_string(split.stats.sahCost));
  RecordProperty("references", std::to_string(split.stats.references));
}

TEST(BvhSplits, TempleRandomIdenticalAndDegenerate) {
  const std::vector<Triangle> random = randomTriangles(2000, 3);
  std::vector<Triangle> degenerate(300);
  for (size_t i = 0; i < degenerate.size(); ++i) {
    const glm::vec3 a = random[i].v[0], b = random[i].v[1];
    degenerate[i].v[0] = a;
    degenerate[i].v[1] = i % 2 ? a : b;                 // a point or a segment
    degenerate[i].v[2] = i % 2 ? a : 0.5f * (a + b);
  }
  for (const std::vector<Triangle>& tris :
       {makeTemple().triangles, random, std::vector<Triangle>(400, random[0]), degenerate})
    expectCovered(tris, buildBvh(tris, kDefaultMaxLeafSize, 0, BvhSplits::Spatial));
}

// Leaf records carry each entry's BVH-order index and bvhOrderTriangles' floats; an entry whose triangle the
// order lacks is refused.
TEST(BvhLeafRecords, EntriesMapToTheBvhOrder) {
  const std::vector<Triangle> tris = randomTriangles(5, 1);
  const std::vector<uint32_t> order = {3, 0, 4, 1, 2};     // BVH-order index -> scene triangle
  const std::vector<uint32_t> entries = {4, 4, 0, 2, 3};   // a split tree's entries, triangle 4 twice
  const std::vector<gpu::GpuLeafTriangle> records = leafRecords(tris, entries, order);
  ASSERT_EQ(records.size(), entries.size());
  const uint32_t expected[] = {2, 2, 1, 4, 0};
  for (size_t e = 0; e < entries.size(); ++e) {
    const Triangle& t = tris[entries[e]];
    EXPECT_EQ(records[e].triangle, expected[e]) << e;
    EXPECT_EQ(records[e].v0, t.v[0]);
    EXPECT_EQ(records[e].e1, t.v[1] - t.v[0]);
    EXPECT_EQ(records[e].e2, t.v[2] - t.v[0]);
  }
  EXPECT_THROW(leafRecords(tris, {1, 5}, order), std::invalid_argument);
  EXPECT_THROW(leafRecords(tris, {1}, {0, 2}), std::invalid_argument);
  EXPECT_THROW(leafRecords(tris, {0}, {0, 9}), std::invalid_argument);
}

}  // namespace
}  // namespace raylab
