// reinsertOptimize (renderer/bvh/bvh_reinsert.h): the tree it leaves holds the same leaves (the same entries in
// the same boxes), every interior box is exactly its children's union, the layout is buildBvh's (depth first,
// siblings adjacent, leaf entries in leaf order), the interior area and the SAH fall, the depth stays within the
// traversal stack, the same rays find the same closest hits, and it is deterministic.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <tuple>
#include <vector>

#include "renderer/bvh/bvh.h"
#include "renderer/bvh/bvh_reinsert.h"
#include "renderer/bvh/bvh_sah.h"
#include "renderer/bvh/bvh_traverse_cpu.h"
#include "renderer/gpu_scene.h"
#include "scenes/procedural.h"
#include "tests/same_tree_hits.h"
#include "tests/scene_checks.h"

namespace raylab {
namespace {

// A leaf as what a ray meets: its box and its scene triangles (sorted; a split tree may repeat one).
using LeafKey = std::tuple<float, float, float, float, float, float, std::vector<uint32_t>>;

std::vector<LeafKey> leafKeysOf(const Bvh& bvh) {
  std::vector<LeafKey> leaves;
  for (const gpu::BvhNode& n : bvh.nodes) {
    if (n.triCount == 0) continue;
    std::vector<uint32_t> tris(bvh.triangleOrder.begin() + n.leftOrFirst,
                               bvh.triangleOrder.begin() + n.leftOrFirst + n.triCount);
    std::sort(tris.begin(), tris.end());
    leaves.push_back({n.boundsMin.x, n.boundsMin.y, n.boundsMin.z, n.boundsMax.x, n.boundsMax.y, n.boundsMax.z, tris});
  }
  std::sort(leaves.begin(), leaves.end());
  return leaves;
}

// Every node reached once from the root, siblings adjacent, interior boxes the exact union of their children's,
// the leaves' entries one after another in the order the leaves are met (depth first, first child first).
void expectWellFormed(const Bvh& bvh) {
  std::vector<uint32_t> reached(bvh.nodes.size(), 0);
  uint32_t nextEntry = 0, deepest = 0, leaves = 0;
  std::vector<std::pair<uint32_t, uint32_t>> stack{{0, 0}};
  while (!stack.empty()) {
    const auto [i, depth] = stack.back();
    stack.pop_back();
    ASSERT_LT(i, bvh.nodes.size());
    ++reached[i];
    deepest = std::max(deepest, depth);
    const gpu::BvhNode& n = bvh.nodes[i];
    if (n.triCount > 0) {
      EXPECT_EQ(n.leftOrFirst, nextEntry) << "leaf " << i << ": entries not in leaf order";
      nextEntry = n.leftOrFirst + n.triCount;
      ++leaves;
      continue;
    }
    ASSERT_LT(n.leftOrFirst + 1, bvh.nodes.size());
    const gpu::BvhNode &a = bvh.nodes[n.leftOrFirst], &b = bvh.nodes[n.leftOrFirst + 1];
    EXPECT_EQ(n.boundsMin, glm::min(a.boundsMin, b.boundsMin)) << "node " << i;
    EXPECT_EQ(n.boundsMax, glm::max(a.boundsMax, b.boundsMax)) << "node " << i;
    stack.push_back({n.leftOrFirst + 1, depth + 1});
    stack.push_back({n.leftOrFirst, depth + 1});
  }
  EXPECT_TRUE(std::all_of(reached.begin(), reached.end(), [](uint32_t r) { return r == 1; }));
  EXPECT_EQ(nextEntry, bvh.triangleOrder.size());
  EXPECT_EQ(bvh.nodes.size(), 2 * size_t(leaves) - 1);
  EXPECT_EQ(bvh.stats.nodeCount, bvh.nodes.size());
  EXPECT_EQ(bvh.stats.leafCount, leaves);
  EXPECT_EQ(bvh.stats.maxDepth, deepest);
  EXPECT_LE(deepest, kMaxBvhDepth);
}

// Long thin boards at random angles: overlapping boxes, which Embree's top-down build leaves room to improve.
std::vector<Triangle> boards(size_t count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-10.0f, 10.0f), len(2.0f, 9.0f), w(0.05f, 0.4f);
  std::vector<Triangle> tris;
  for (size_t i = 0; i < count; ++i) {
    const glm::vec3 a{u(rng), u(rng), u(rng)};
    const glm::vec3 along = glm::normalize(glm::vec3(u(rng), u(rng), u(rng))) * len(rng);
    const glm::vec3 across = glm::normalize(glm::cross(along, glm::vec3(u(rng), u(rng), u(rng)))) * w(rng);
    tris.push_back(Triangle{{a, a + along, a + across}});
    tris.push_back(Triangle{{a + along, a + along + across, a + across}});
  }
  return tris;
}

TEST(BvhReinsert, SameLeavesLowerAreaWellFormedAndDeterministic) {
  for (const auto& [name, tris] : {std::pair{"boards", boards(3000, 5)}, std::pair{"temple", makeTemple().triangles},
                                   std::pair{"random", randomTriangles(4000, 9)}}) {
    SCOPED_TRACE(name);
    for (BvhSplits splits : {BvhSplits::Spatial, BvhSplits::None}) {
      const Bvh built = buildBvh(tris, kSpatialSplitMaxLeafSize, 0, splits);
      Bvh optimized = built;
      const ReinsertStats stats = reinsertOptimize(optimized, 8);
      EXPECT_GE(stats.passes, 1u);
      EXPECT_GT(stats.reinserted, 0u) << "nothing moved: the test proves nothing";
      EXPECT_LT(stats.areaAfter, stats.areaBefore);
      EXPECT_LT(optimized.stats.sahCost, built.stats.sahCost);
      EXPECT_DOUBLE_EQ(optimized.stats.sahCost, bvhSahCost(optimized));
      EXPECT_EQ(optimized.stats.references, built.stats.references);
      expectWellFormed(optimized);
      EXPECT_EQ(optimized.nodes[0].boundsMin, built.nodes[0].boundsMin);
      EXPECT_EQ(optimized.nodes[0].boundsMax, built.nodes[0].boundsMax);
      EXPECT_TRUE(leafKeysOf(optimized) == leafKeysOf(built)) << "the leaves changed";
      Bvh again = built;
      reinsertOptimize(again, 8);
      EXPECT_TRUE(std::equal(again.nodes.begin(), again.nodes.end(), optimized.nodes.begin(), optimized.nodes.end(),
                             [](const gpu::BvhNode& a, const gpu::BvhNode& b) {
                               return a.boundsMin == b.boundsMin && a.boundsMax == b.boundsMax &&
                                      a.leftOrFirst == b.leftOrFirst && a.triCount == b.triCount;
                             }));
      EXPECT_EQ(again.triangleOrder, optimized.triangleOrder);
    }
  }
}

// The same rays meet the same closest triangle at the same distance in both trees (the boxes a ray enters
// change, the leaves it can hit do not), and shadow rays are blocked alike.
TEST(BvhReinsert, RaysFindTheSameHits) {
  const std::vector<Triangle> tris = boards(3000, 11);
  const Bvh built = buildBvh(tris, kSpatialSplitMaxLeafSize, 0, BvhSplits::Spatial);
  Bvh optimized = built;
  ASSERT_GT(reinsertOptimize(optimized, 8).reinserted, 0u);
  const SameTreeHits same = expectSameHits(tris, built, optimized, 20000, 4);
  EXPECT_GT(same.hits, 5000u);
  EXPECT_GT(same.blocked, 1000u);
  RecordProperty("steps_before", std::to_string(same.stepsA));
  RecordProperty("steps_after", std::to_string(same.stepsB));
}

// Nothing to do: no passes, an empty scene, a tree too small to rearrange.
TEST(BvhReinsert, LeavesTreesWithNothingToDoAsTheyAre) {
  const std::vector<Triangle> tris = randomTriangles(500, 2);
  Bvh bvh = buildBvh(tris, kSpatialSplitMaxLeafSize, 0, BvhSplits::Spatial);
  const std::vector<uint32_t> order = bvh.triangleOrder;
  const size_t nodes = bvh.nodes.size();
  EXPECT_EQ(reinsertOptimize(bvh, 0).reinserted, 0u);
  EXPECT_EQ(bvh.triangleOrder, order);
  EXPECT_EQ(bvh.nodes.size(), nodes);
  for (size_t count : {size_t(0), size_t(1), size_t(3)}) {
    Bvh small = buildBvh(randomTriangles(count, 1), 1, 0, BvhSplits::Spatial);
    const size_t before = small.nodes.size();
    const ReinsertStats s = reinsertOptimize(small, 4);
    EXPECT_EQ(s.reinserted, 0u) << count << " triangles";
    EXPECT_EQ(small.nodes.size(), before);
  }
}

}  // namespace
}  // namespace raylab
