// Presplitting (renderer/bvh/bvh_presplit.h): the pieces of a cut reference are tighter boxes that still cover
// the triangle, the cuts stop at their budget and never touch a degenerate triangle, the order is deterministic;
// a tree built from presplit references holds every triangle, none twice in a leaf, and finds the same hits as
// the tree built without them.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <vector>

#include "renderer/bvh/bvh.h"
#include "renderer/bvh/bvh_presplit.h"
#include "renderer/bvh/bvh_traverse_cpu.h"
#include "renderer/gpu_scene.h"
#include "scenes/procedural.h"
#include "tests/same_tree_hits.h"

namespace raylab {
namespace {

RTCBuildPrimitive referenceOf(const Triangle& t, uint32_t index) {
  const glm::vec3 lo = glm::min(t.v[0], glm::min(t.v[1], t.v[2])), hi = glm::max(t.v[0], glm::max(t.v[1], t.v[2]));
  RTCBuildPrimitive p{};
  p.lower_x = lo.x, p.lower_y = lo.y, p.lower_z = lo.z, p.upper_x = hi.x, p.upper_y = hi.y, p.upper_z = hi.z;
  p.geomID = 0, p.primID = index;
  return p;
}

bool inside(const RTCBuildPrimitive& p, glm::vec3 q) {
  return q.x >= p.lower_x && q.x <= p.upper_x && q.y >= p.lower_y && q.y <= p.upper_y && q.z >= p.lower_z &&
         q.z <= p.upper_z;
}

float boxArea(const RTCBuildPrimitive& p) {
  const float dx = p.upper_x - p.lower_x, dy = p.upper_y - p.lower_y, dz = p.upper_z - p.lower_z;
  return 2.0f * (dx * dy + dy * dz + dz * dx);
}

// Long thin diagonal planks: the boxes with the most empty space, which presplitting is for.
std::vector<Triangle> diagonalPlanks(size_t count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-10.0f, 10.0f), w(0.05f, 0.3f);
  std::vector<Triangle> tris;
  for (size_t i = 0; i < count; ++i) {
    const glm::vec3 a{u(rng), u(rng), u(rng)}, b{u(rng), u(rng), u(rng)};
    const glm::vec3 across = glm::normalize(glm::cross(b - a, glm::vec3(u(rng), u(rng), u(rng)))) * w(rng);
    tris.push_back(Triangle{{a, b, a + across}});
    tris.push_back(Triangle{{b, b + across, a + across}});
  }
  return tris;
}

TEST(BvhPresplit, PiecesAreTighterBoxesThatCoverTheTriangle) {
  const std::vector<Triangle> tris{Triangle{{glm::vec3(0.0f), glm::vec3(8.0f, 6.0f, 4.0f), glm::vec3(0.2f, 0.0f, 0.1f)}}};
  std::vector<RTCBuildPrimitive> prims(1 + 7);
  prims[0] = referenceOf(tris[0], 0);
  const float whole = boxArea(prims[0]);
  ASSERT_GT(presplitPriority(prims[0], tris[0]), 0.0f);
  const size_t count = presplitReferences(prims.data(), 1, 7, tris);
  ASSERT_EQ(count, 8u);
  float pieces = 0.0f;
  for (size_t i = 0; i < count; ++i) {
    EXPECT_EQ(prims[i].primID, 0u);
    EXPECT_TRUE(std::isfinite(boxArea(prims[i])));
    const RTCBuildPrimitive full = referenceOf(tris[0], 0);
    EXPECT_TRUE(inside(full, {prims[i].lower_x, prims[i].lower_y, prims[i].lower_z})) << "piece " << i;
    EXPECT_TRUE(inside(full, {prims[i].upper_x, prims[i].upper_y, prims[i].upper_z})) << "piece " << i;
    pieces += boxArea(prims[i]);
  }
  EXPECT_LT(pieces, 0.5f * whole) << "eight pieces of a long diagonal triangle should leave most of its box out";
  // Every point of the triangle lies in some piece.
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int s = 0; s < 2000; ++s) {
    float a = u(rng), b = u(rng);
    if (a + b > 1.0f) a = 1.0f - a, b = 1.0f - b;
    const glm::vec3 q = tris[0].v[0] + a * (tris[0].v[1] - tris[0].v[0]) + b * (tris[0].v[2] - tris[0].v[0]);
    EXPECT_TRUE(std::any_of(prims.begin(), prims.begin() + count, [&](const RTCBuildPrimitive& p) { return inside(p, q); }))
        << "sample " << s;
  }
}

TEST(BvhPresplit, CutsStopAtTheBudgetSkipDegenerateTrianglesAndRepeat) {
  std::vector<Triangle> tris = diagonalPlanks(50, 3);
  tris.push_back(Triangle{{glm::vec3(1.0f), glm::vec3(2.0f), glm::vec3(3.0f)}});  // a line: zero area
  std::vector<RTCBuildPrimitive> prims(tris.size() + 40), again(tris.size() + 40);
  for (size_t i = 0; i < tris.size(); ++i) prims[i] = again[i] = referenceOf(tris[i], static_cast<uint32_t>(i));
  EXPECT_EQ(presplitPriority(prims.back(), tris.back()), 0.0f);
  EXPECT_EQ(presplitReferences(prims.data(), tris.size(), 0, tris), tris.size());
  const size_t count = presplitReferences(prims.data(), tris.size(), 40, tris);
  EXPECT_EQ(count, tris.size() + 40);
  EXPECT_EQ(presplitReferences(again.data(), tris.size(), 40, tris), count);
  for (size_t i = 0; i < count; ++i) {
    EXPECT_EQ(prims[i].primID, again[i].primID) << i;
    EXPECT_EQ(boxArea(prims[i]), boxArea(again[i])) << i;
  }
  EXPECT_EQ(std::count_if(prims.begin(), prims.begin() + count,
                          [&](const RTCBuildPrimitive& p) { return p.primID == tris.size() - 1; }),
            1) << "the degenerate triangle was cut";
}

// A triangle in an axis plane fills its flat box with its quad's other half: never cut, even where it has the
// largest box (the temple's ground), while a wall leaning by a fraction of a degree (Sponza's) is cut first.
TEST(BvhPresplit, AxisAlignedTrianglesAreNeverCut) {
  const float noise = 0.1f * kPresplitFlatness * 150.0f;  // within the flatness tolerance of a 150-unit side
  const float lean = 30.0f * kPresplitFlatness * 30.0f;   // well past it on a 30-unit side
  const std::vector<Triangle> tris{
      Triangle{{glm::vec3(-75.0f, 0.0f, -75.0f), glm::vec3(75.0f, 0.0f, -75.0f), glm::vec3(75.0f, 0.0f, 75.0f)}},
      Triangle{{glm::vec3(-75.0f, 0.0f, -75.0f), glm::vec3(75.0f, noise, 75.0f), glm::vec3(-75.0f, 0.0f, 75.0f)}},
      Triangle{{glm::vec3(5.0f, 0.0f, 0.0f), glm::vec3(5.0f + lean, 20.0f, 0.0f), glm::vec3(5.0f + lean, 20.0f, 30.0f)}}};
  std::vector<RTCBuildPrimitive> prims(tris.size() + 6);
  for (size_t i = 0; i < tris.size(); ++i) prims[i] = referenceOf(tris[i], static_cast<uint32_t>(i));
  EXPECT_EQ(presplitPriority(prims[0], tris[0]), 0.0f);
  EXPECT_EQ(presplitPriority(prims[1], tris[1]), 0.0f);
  EXPECT_GT(presplitPriority(prims[2], tris[2]), 0.0f);
  const size_t count = presplitReferences(prims.data(), tris.size(), 6, tris);
  EXPECT_EQ(count, tris.size() + 6);
  for (uint32_t ground = 0; ground < 2; ++ground)
    EXPECT_EQ(std::count_if(prims.begin(), prims.begin() + count, [&](const RTCBuildPrimitive& p) { return p.primID == ground; }), 1)
        << "ground triangle " << ground << " was cut";
}

// The tree over presplit references: every triangle in some leaf and none twice in one (two pieces of a
// triangle meeting in a leaf hold it once), more references than without, and the same closest hits and
// shadow answers as the tree without presplitting.
TEST(BvhPresplit, TreeHoldsEveryTriangleOnceALeafAndFindsTheSameHits) {
  const std::vector<Triangle> tris = diagonalPlanks(1500, 7);
  const Bvh plain = buildBvh(tris, kSpatialSplitMaxLeafSize, 0, BvhSplits::Spatial);
  const Bvh presplit = buildBvh(tris, kSpatialSplitMaxLeafSize, 0, BvhSplits::Spatial, 0.2);
  EXPECT_GT(presplit.stats.references, plain.stats.references);
  std::vector<uint32_t> seen(tris.size(), 0);
  for (const gpu::BvhNode& n : presplit.nodes) {
    if (n.triCount == 0) continue;
    std::set<uint32_t> leaf;
    for (uint32_t e = n.leftOrFirst; e < n.leftOrFirst + n.triCount; ++e) {
      EXPECT_TRUE(leaf.insert(presplit.triangleOrder[e]).second) << "a triangle twice in one leaf";
      ++seen[presplit.triangleOrder[e]];
    }
  }
  EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](uint32_t s) { return s > 0; }));
  const SameTreeHits same = expectSameHits(tris, plain, presplit, 20000, 5);
  EXPECT_GT(same.hits, 5000u);
  EXPECT_GT(same.blocked, 1000u);
}

}  // namespace
}  // namespace raylab
