// Structural checks of the BVH builder (Embree's rtcBuildBVH flattened into our layout): every triangle in
// exactly one leaf, children inside parents, siblings adjacent and depth first, depth within the shaders'
// traversal stack, degenerate inputs handled, and the tree's SAH cost against references.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

#include "renderer/bvh/bvh.h"
#include "renderer/bvh/bvh_pairs.h"
#include "renderer/bvh/bvh_sah.h"
#include "renderer/bvh/bvh_traverse_cpu.h"
#include "tests/scene_checks.h"
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
  EXPECT_EQ(bvh.stats.maxDepth, maxDepth);
  EXPECT_EQ(bvh.stats.nodeCount, bvh.nodes.size());
  // A binary tree with L leaves has 2L - 1 nodes; anything more is unreachable.
  EXPECT_EQ(bvh.nodes.size(), 2 * size_t(bvh.stats.leafCount) - 1);
}

// Depth-first with adjacent siblings: walking left subtrees first visits the child pairs in array order, and
// leaves come in triangle order (what the traversal's memory access and the wide-BVH collapse rely on).
void checkDepthFirstLayout(const Bvh& bvh) {
  uint32_t nextPair = 1, nextTriangle = 0;
  std::vector<uint32_t> stack{0u};
  while (!stack.empty()) {
    const gpu::BvhNode& n = bvh.nodes[stack.back()];
    stack.pop_back();
    if (n.triCount > 0) {
      ASSERT_EQ(n.leftOrFirst, nextTriangle);
      nextTriangle += n.triCount;
      continue;
    }
    ASSERT_EQ(n.leftOrFirst, nextPair);
    nextPair += 2;
    stack.push_back(n.leftOrFirst + 1);
    stack.push_back(n.leftOrFirst);
  }
  EXPECT_EQ(nextPair, bvh.nodes.size());
  EXPECT_EQ(nextTriangle, bvh.triangleOrder.size());
}

// A simple reference builder: object median on the longest axis of the centroid bounds, down to 4
// triangles. Its SAH cost is the bar any SAH builder must clear.
struct MedianSplitBuilder {
  const std::vector<Triangle>& tris;
  Bvh bvh;

  static glm::vec3 centroid(const Triangle& t) { return (t.v[0] + t.v[1] + t.v[2]) / 3.0f; }

  void build(uint32_t slot, uint32_t first, uint32_t count) {
    Bounds b, c;
    for (uint32_t i = first; i < first + count; ++i) {
      for (const glm::vec3& v : tris[bvh.triangleOrder[i]].v) b.grow(v);
      c.grow(centroid(tris[bvh.triangleOrder[i]]));
    }
    bvh.nodes[slot].boundsMin = b.min;
    bvh.nodes[slot].boundsMax = b.max;
    if (count <= 4) {
      bvh.nodes[slot].leftOrFirst = first;
      bvh.nodes[slot].triCount = count;
      return;
    }
    glm::vec3 e = c.extent();
    int axis = e.x > e.y ? (e.x > e.z ? 0 : 2) : (e.y > e.z ? 1 : 2);
    auto begin = bvh.triangleOrder.begin() + first;
    std::nth_element(begin, begin + count / 2, begin + count,
                     [&](uint32_t a, uint32_t z) { return centroid(tris[a])[axis] < centroid(tris[z])[axis]; });
    uint32_t left = static_cast<uint32_t>(bvh.nodes.size());
    bvh.nodes.resize(bvh.nodes.size() + 2);
    bvh.nodes[slot].leftOrFirst = left;
    bvh.nodes[slot].triCount = 0;
    build(left, first, count / 2);
    build(left + 1, first + count / 2, count - count / 2);
  }

  static Bvh make(const std::vector<Triangle>& tris) {
    MedianSplitBuilder m{tris, {}};
    m.bvh.triangleOrder.resize(tris.size());
    for (uint32_t i = 0; i < tris.size(); ++i) m.bvh.triangleOrder[i] = i;
    m.bvh.nodes.resize(1);
    m.build(0, 0, static_cast<uint32_t>(tris.size()));
    return m.bvh;
  }
};

TEST(Bvh, TempleIsWellFormed) {
  Scene temple = makeTemple();
  Bvh bvh = buildBvh(temple.triangles);
  checkBvh(temple.triangles, bvh);
  checkDepthFirstLayout(bvh);
  EXPECT_GT(bvh.stats.leafCount, temple.triangles.size() / 8);
  EXPECT_LE(bvh.stats.largestLeaf, 8u);
}

TEST(Bvh, RandomTrianglesAndIdenticalTriangles) {
  const std::vector<Triangle> tris = randomTriangles(3000, 3);
  checkBvh(tris, buildBvh(tris));
  // Many triangles at the same place cannot be split by SAH; the builder must still terminate and
  // stay within the stack depth.
  std::vector<Triangle> same(500, tris[0]);
  checkBvh(same, buildBvh(same));
  // The SAH is free to choose leaf sizes below the limit: with a limit of 1 every leaf has one triangle.
  Bvh ones = buildBvh(tris, 1);
  checkBvh(tris, ones);
  EXPECT_EQ(ones.stats.largestLeaf, 1u);
  EXPECT_EQ(ones.stats.leafCount, tris.size());
}

TEST(Bvh, SingleTriangle) {
  std::vector<Triangle> one(1);
  one[0].v[1] = {1, 0, 0};
  one[0].v[2] = {0, 1, 0};
  Bvh bvh = buildBvh(one);
  checkBvh(one, bvh);
  EXPECT_EQ(bvh.nodes.size(), 1u);
  EXPECT_EQ(bvh.nodes[0].triCount, 1u);
  EXPECT_EQ(bvh.nodes[0].boundsMax, glm::vec3(1, 1, 0));
}

// gpu_scene.cpp uploads whatever comes back (the app refuses scenes without triangles before, but the tests'
// scenes and a library caller may not): an interior root whose inverted box no ray enters.
TEST(Bvh, ZeroTrianglesGiveATreeNoRayEnters) {
  Bvh bvh = buildBvh({});
  EXPECT_TRUE(bvh.triangleOrder.empty());
  ASSERT_EQ(bvh.nodes.size(), 3u);
  EXPECT_EQ(bvh.nodes[0].triCount, 0u);
  EXPECT_EQ(bvh.nodes[0].leftOrFirst, 1u);
  EXPECT_GT(bvh.nodes[0].boundsMin.x, bvh.nodes[0].boundsMax.x);
  EXPECT_TRUE(isEmptyTree(bvh.nodes));
  EXPECT_EQ(bvh.stats.leafCount, 0u);
  EXPECT_EQ(bvhSahCost(bvh), 0.0);
  // The CPU twin misses at once (its slab test alone would enter the inverted boxes and loop over nodes that
  // point at each other).
  for (glm::vec3 dir : {glm::vec3(0, 0, 1), glm::vec3(1, -1, 0.5f)}) {
    const CpuHit hit = traverseBinaryCpu(bvh.nodes, {}, glm::vec3(0.5f), dir, 1e30f, false);
    EXPECT_LT(hit.t, 0.0f);
    EXPECT_EQ(hit.steps, 0u);
  }
}

// Zero-area triangles (points, segments, flat slivers) and triangles lying in an axis plane (a flat box)
// must each land in one leaf whose box holds their corners.
TEST(Bvh, DegenerateTriangles) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-5.0f, 5.0f);
  std::vector<Triangle> tris;
  for (int i = 0; i < 600; ++i) {
    glm::vec3 a{u(rng), u(rng), u(rng)}, b{u(rng), u(rng), u(rng)};
    Triangle t;
    switch (i % 4) {
      case 0: t.v[0] = t.v[1] = t.v[2] = a; break;                    // a point
      case 1: t.v[0] = a, t.v[1] = b, t.v[2] = 0.5f * (a + b); break;  // a segment
      case 2: t.v[0] = a, t.v[1] = b, t.v[2] = {a.x, b.y, 0.0f}; t.v[0].z = t.v[1].z = 0.0f; break;  // in z = 0
      default: t.v[0] = a, t.v[1] = b, t.v[2] = b + glm::vec3(1e-7f); break;  // a sliver
    }
    tris.push_back(t);
  }
  checkBvh(tris, buildBvh(tris));
  std::vector<Triangle> points(tris.begin(), tris.begin() + 1);
  checkBvh(points, buildBvh(points));
}

// A vertex at infinity or NaN has no box; the loaders refuse such scenes, and the builder says so too
// instead of handing Embree bounds it cannot order.
TEST(Bvh, NonFiniteVertexIsRefused) {
  std::vector<Triangle> tris(3);
  tris[1].v[2].y = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(buildBvh(tris), std::invalid_argument);
  tris[1].v[2].y = std::numeric_limits<float>::infinity();
  EXPECT_THROW(buildBvh(tris), std::invalid_argument);
}

// The boxes are computed in chunks on several threads; the message names the lowest bad triangle however
// the chunks are shared out.
TEST(Bvh, NonFiniteVertexMessageNamesTheFirst) {
  std::vector<Triangle> tris(1000, Triangle{{glm::vec3(0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)}});
  tris[917].v[0].x = std::numeric_limits<float>::infinity();
  tris[312].v[1].z = std::numeric_limits<float>::quiet_NaN();
  tris[313].v[2].y = -std::numeric_limits<float>::infinity();
  for (uint32_t threads : {1u, 3u, 7u, 0u}) {
    try {
      buildBvh(tris, 8, threads);
      ADD_FAILURE() << "no exception with " << threads << " threads";
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()), "buildBvh: triangle 312 has a non-finite vertex") << threads << " threads";
    }
  }
}

void expectSameBvh(const Bvh& a, const Bvh& b, const std::string& what) {
  ASSERT_EQ(a.nodes.size(), b.nodes.size()) << what;
  EXPECT_EQ(std::memcmp(a.nodes.data(), b.nodes.data(), a.nodes.size() * sizeof(gpu::BvhNode)), 0) << what;
  EXPECT_EQ(a.triangleOrder, b.triangleOrder) << what;
  EXPECT_EQ(a.stats.nodeCount, b.stats.nodeCount) << what;
  EXPECT_EQ(a.stats.leafCount, b.stats.leafCount) << what;
  EXPECT_EQ(a.stats.maxDepth, b.stats.maxDepth) << what;
  EXPECT_EQ(a.stats.largestLeaf, b.stats.largestLeaf) << what;
  EXPECT_EQ(a.stats.maxLeafSize, b.stats.maxLeafSize) << what;
}

// The phases around Embree's build, which share their work out among threads, give the same arrays, bit for
// bit, on one thread and on several (more than this machine may have: how the work is split depends on the
// count, not on the hardware). Embree's own build is deterministic.
TEST(Bvh, SameTreeOnAnyThreadCount) {
  const std::vector<Triangle> random = randomTriangles(20000, 5);
  const std::vector<std::pair<std::string, std::vector<Triangle>>> inputs = {
      {"temple", makeTemple().triangles}, {"random", random}, {"identical", std::vector<Triangle>(3000, random[0])}};
  for (const auto& [name, tris] : inputs) {
    for (uint32_t leaf : {1u, 8u}) {
      const Bvh one = buildBvh(tris, leaf, 1);
      checkDepthFirstLayout(one);
      for (uint32_t threads : {2u, 5u, 16u, 0u})
        expectSameBvh(one, buildBvh(tris, leaf, threads),
                      name + ", leaf " + std::to_string(leaf) + ", " + std::to_string(threads) + " threads");
    }
  }
}

// Pathological inputs for the depth bound: 100,000 triangles at one place (no split separates them: only
// Embree's fallback halving), and a geometric series of sizes, each triangle 1.25 times the last, which
// SAH peels off a few at a time. Both must stay below RL_BVH_STACK with every triangle kept.
TEST(Bvh, DepthBoundOnPathologicalInputs) {
  Triangle t;
  t.v[0] = {0, 0, 0};  // glm leaves a vec3 uninitialised
  t.v[1] = {1, 0, 0};
  t.v[2] = {0, 1, 0};
  std::vector<Triangle> same(100000, t);
  Bvh bvh = buildBvh(same);
  checkBvh(same, bvh);
  EXPECT_GT(bvh.stats.maxDepth, 10u);  // halved down to small leaves, not one huge leaf
  std::vector<Triangle> series;
  float s = 1.0f;
  for (int i = 0; i < 180; ++i, s *= 1.25f) {
    Triangle g;
    g.v[0] = glm::vec3(s, 0, 0);
    g.v[1] = glm::vec3(2 * s, 0, 0);
    g.v[2] = glm::vec3(s, s, 0);
    for (int k = 0; k < 20; ++k) series.push_back(g);  // 20 copies: leaves must also split copies
  }
  Bvh deep = buildBvh(series, 1);
  checkBvh(series, deep);
  checkDepthFirstLayout(deep);
  RecordProperty("series_depth", std::to_string(deep.stats.maxDepth));
  RecordProperty("series_leaf_limit", std::to_string(deep.stats.maxLeafSize));
}

// The SAH cost (bvh_sah.h) of a hand-made tree of two unit squares' triangles, computed by hand.
TEST(BvhSah, CostOfAHandMadeTree) {
  Bvh bvh;
  bvh.triangleOrder = {0, 1};
  // Root: the box [0,2]x[0,1]x[0,0] (area 2 * 2 = 4); leaves: [0,1]^2 and [1,2]x[0,1] (area 2 each), one
  // triangle each: (4 * 1 + 2 * 1 + 2 * 1) / 4 = 2 with both costs 1; with traversal 3, intersection 0.5:
  // (4 * 3 + 2 * 0.5 + 2 * 0.5) / 4 = 3.5.
  bvh.nodes = {{glm::vec3(0), 1u, glm::vec3(2, 1, 0), 0u},
               {glm::vec3(0), 0u, glm::vec3(1, 1, 0), 1u},
               {glm::vec3(1, 0, 0), 1u, glm::vec3(2, 1, 0), 1u}};
  EXPECT_DOUBLE_EQ(bvhSahCost(bvh), 2.0);
  EXPECT_DOUBLE_EQ(bvhSahCost(bvh, 3.0, 0.5), 3.5);
  bvh.nodes.resize(1);
  bvh.nodes[0].triCount = 2;  // one leaf: the root's area cancels
  bvh.nodes[0].leftOrFirst = 0;
  EXPECT_DOUBLE_EQ(bvhSahCost(bvh), 2.0);
}

// Embree's tree against two references on the temple: the hand-written binned SAH builder it replaced
// (28.25 on this temple at revision 4d7b2fe: raylab_bvh_report, docs/results/embree-bvh/README.md), and a
// median-split tree built here (much worse: it ignores the SAH).
TEST(BvhSah, TempleTreeNoWorseThanReferences) {
  Scene temple = makeTemple();
  Bvh bvh = buildBvh(temple.triangles);
  double embree = bvhSahCost(bvh);
  double median = bvhSahCost(MedianSplitBuilder::make(temple.triangles));
  constexpr double kHandWrittenBinnedSah = 28.25;
  EXPECT_DOUBLE_EQ(bvh.stats.sahCost, embree);
  EXPECT_LE(embree, kHandWrittenBinnedSah);
  EXPECT_LT(embree, median);
  RecordProperty("sah_embree", std::to_string(embree));
  RecordProperty("sah_median_split", std::to_string(median));
}


// The traversal carries a leaf child as one word (shaders/shared_types.h, RL_LEAF_TAG): a leaf of the most
// triangles that word holds becomes a pair node whose slot keeps its range; one triangle more, or a first
// entry past the word's limit, is refused by name rather than traced wrong.
TEST(BvhPairs, LeavesMustFitTheTraversalsLeafWord) {
  constexpr uint32_t most = 1u << RL_LEAF_COUNT_BITS;
  Bvh bvh;
  bvh.nodes = {{glm::vec3(0), 1u, glm::vec3(2, 1, 0), 0u},
               {glm::vec3(0), 0u, glm::vec3(1, 1, 0), most},
               {glm::vec3(1, 0, 0), most, glm::vec3(2, 1, 0), 1u}};
  const std::vector<gpu::BvhPairNode> pairs = pairNodes(bvh);
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0].child[0], RL_LEAF_TAG | (most - 1u));
  EXPECT_EQ(pairs[0].child[1], RL_LEAF_TAG | (most << RL_LEAF_COUNT_BITS));
  bvh.nodes[1].triCount = most + 1;
  EXPECT_THROW(pairNodes(bvh), std::invalid_argument);
  bvh.nodes[1].triCount = most;
  bvh.nodes[2].leftOrFirst = RL_LEAF_ENTRY_LIMIT;
  EXPECT_THROW(pairNodes(bvh), std::invalid_argument);
}

// A tree without triangles (buildBvh's empty tree) becomes one pair node whose two slots hold RL_BVH_NO_CHILD
// behind boxes at +infinity, which the traversal's slab test (shaders/bvh_traverse.glsl, enterPair, written
// out here) never enters, whatever the ray: the traversal does not check the word.
TEST(BvhPairs, AnEmptyTreeHasBoxesNoRayEnters) {
  const std::vector<gpu::BvhPairNode> pairs = pairNodes(buildBvh({}));
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0].child[0], RL_BVH_NO_CHILD);
  EXPECT_EQ(pairs[0].child[1], RL_BVH_NO_CHILD);
  const glm::vec4 bounds[3] = {pairs[0].xBounds, pairs[0].yBounds, pairs[0].zBounds};
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  const glm::vec3 directions[] = {{1, 0, 0}, {0, -1, 0}, {0, 0, 1}, {-1, -1, -1}, {0, 0, 0}};
  for (int r = 0; r < 200; ++r) {
    const glm::vec3 origin = glm::vec3(u(rng), u(rng), u(rng)) * 1e6f;
    const glm::vec3 dir = r < 5 ? directions[r] : glm::vec3(u(rng), u(rng), u(rng));
    for (int slot = 0; slot < 2; ++slot) {
      float enter = 0.0f, leave = 1e30f;
      for (int k = 0; k < 3; ++k) {
        const float eps = 1e-20f;  // safeInverse's
        const float inv = 1.0f / (std::abs(dir[k]) > eps ? dir[k] : (dir[k] >= 0.0f ? eps : -eps));
        const float t0 = bounds[k][2 * slot] * inv - origin[k] * inv;
        const float t1 = bounds[k][2 * slot + 1] * inv - origin[k] * inv;
        enter = std::max(enter, std::min(t0, t1));
        leave = std::min(leave, std::max(t0, t1));
      }
      EXPECT_GT(enter, leave) << "ray " << r << ", slot " << slot;
    }
  }
}

}  // namespace
}  // namespace raylab
