// The wide BVH collapsed from the binary one: its structure (every triangle in exactly one leaf, every
// quantized child box containing the exact box of everything below it, depth within the stack) and its
// traversal (the C++ twin of shaders/bvh_traverse_wide.glsl) against the binary tree's, ray for ray, on the
// temple, random triangles and Sponza where ../shared/scenes has it.
#include <gtest/gtest.h>

#include <bit>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <random>

#include "app/tracebench/trace_rays.h"
#include "renderer/bvh/bvh_traverse_cpu.h"
#include "renderer/bvh/bvh_wide.h"
#include "renderer/bvh/bvh_wide_slots.h"
#include "tests/scene_checks.h"
#include "renderer/gpu_scene.h"
#include "renderer/path_tracer.h"
#include "scenes/gltf_loader.h"
#include "scenes/procedural.h"

namespace raylab {
namespace {

struct ExactBox {
  glm::vec3 min{1e30f}, max{-1e30f};
  void grow(glm::vec3 p) { min = glm::min(min, p), max = glm::max(max, p); }
  void grow(const ExactBox& b) { min = glm::min(min, b.min), max = glm::max(max, b.max); }
};

bool inside(const ExactBox& exact, const WideChildBox& q) {
  return glm::all(glm::lessThanEqual(q.min, exact.min)) && glm::all(glm::greaterThanEqual(q.max, exact.max));
}

struct WideWalk {
  const BvhWide& wide;
  const std::vector<Triangle>& triangles;  // scene order
  const std::vector<uint32_t>& order;      // BVH position -> scene index
  std::vector<int> triangleSeen, nodeSeen;
  uint32_t maxDepth = 0, leafSlots = 0;
  uint64_t boxes = 0, boxesNotContaining = 0;

  // The exact box of node `index`'s subtree, from its triangles' corners; checks every child's quantized box
  // and that the node's leaves are one block of at most 32 triangles, each leaf's bits within the mask.
  ExactBox walk(uint32_t index, uint32_t depth) {
    nodeSeen.at(index)++;
    maxDepth = std::max(maxDepth, depth);
    const gpu::BvhWideNode& n = wide.nodes.at(index);
    ExactBox all;
    uint32_t maskBits = 0;
    for (uint32_t s = 0; s < RL_BVH_WIDTH; ++s) {
      const WideSlot kind = slotKind(n, s);
      if (kind == WideSlot::Empty) continue;
      ExactBox exact;
      if (kind == WideSlot::Interior) {
        EXPECT_EQ(wideMeta(n, s), 0u) << "an interior slot with a leaf's meta byte, node " << index;
        exact = walk(slotChildIndex(n, s), depth + 1);
      } else {
        const WideLeafRange leaf = wideLeafRange(n, s);
        ++leafSlots;
        const uint32_t bits = wideLeafBits(wideMeta(n, s));
        EXPECT_EQ(uint32_t(std::popcount(bits)), leaf.count);
        EXPECT_EQ(bits & maskBits, 0u) << "leaves overlapping in node " << index;
        EXPECT_LE((wideMeta(n, s) & 31u) + leaf.count, kWideNodeTriangles);
        maskBits |= bits;
        for (uint32_t i = leaf.first; i < leaf.first + leaf.count; ++i) {
          const uint32_t t = order.at(i);
          triangleSeen.at(t)++;
          for (const glm::vec3& v : triangles[t].v) exact.grow(v);
        }
      }
      ++boxes;
      if (!inside(exact, decodeChildBox(n, s))) ++boxesNotContaining;
      all.grow(exact);
    }
    // One block: the mask's bits contiguous (from bit 0, or bit 1 when every leaf is one triangle).
    if (maskBits != 0) {
      const uint32_t run = maskBits >> std::countr_zero(maskBits);
      EXPECT_EQ(run & (run + 1u), 0u) << "node " << index << "'s leaves are not one block";
      EXPECT_LE(std::countr_zero(maskBits), 1);
    }
    return all;
  }
};

// The binary tree after the collapse moved its leaves: still every triangle once, each leaf's triangles inside
// its box (the collapse moved whole leaves).
void checkBinaryLeaves(const std::vector<Triangle>& tris, const Bvh& binary) {
  std::vector<int> seen(tris.size(), 0);
  for (size_t i = 0; i < binary.nodes.size(); ++i) {
    const gpu::BvhNode& n = binary.nodes[i];
    if (n.triCount == 0) continue;
    ExactBox b;
    for (uint32_t k = n.leftOrFirst; k < n.leftOrFirst + n.triCount; ++k) {
      const uint32_t t = binary.triangleOrder.at(k);
      seen.at(t)++;
      for (const glm::vec3& v : tris[t].v) b.grow(v);
    }
    if (i > 0) {
      ASSERT_TRUE(glm::all(glm::lessThanEqual(n.boundsMin, b.min)) && glm::all(glm::greaterThanEqual(n.boundsMax, b.max)))
          << "binary leaf " << i << " holds triangles outside its box";
    }
  }
  for (size_t t = 0; t < tris.size(); ++t) ASSERT_EQ(seen[t], 1) << "triangle " << t << " in the binary leaves";
}

void checkStructure(const std::vector<Triangle>& tris, const Bvh& binary, const BvhWide& wide) {
  WideWalk w{wide, tris, binary.triangleOrder, std::vector<int>(tris.size(), 0), std::vector<int>(wide.nodes.size(), 0)};
  w.walk(0, 0);
  EXPECT_EQ(w.boxesNotContaining, 0u) << "of " << w.boxes << " quantized boxes";
  for (size_t t = 0; t < tris.size(); ++t) ASSERT_EQ(w.triangleSeen[t], 1) << "triangle " << t;
  for (size_t i = 0; i < wide.nodes.size(); ++i) ASSERT_EQ(w.nodeSeen[i], 1) << "wide node " << i;
  checkBinaryLeaves(tris, binary);
  EXPECT_EQ(w.maxDepth, wide.stats.maxDepth);
  EXPECT_LT(w.maxDepth, uint32_t(RL_BVH_STACK));
  EXPECT_LE(w.maxDepth, binary.stats.maxDepth);
  EXPECT_EQ(wide.stats.nodeCount, wide.nodes.size());
  EXPECT_EQ(wide.stats.leafCount, w.leafSlots);
  // A leaf slot holds at most 8 triangles, all of one binary leaf or all under one binary node: at least one
  // slot per 8 triangles, at most as many as the binary leaves' slots of 8. A wide node stands for a binary
  // interior node or holds a binary leaf; its 8 slots hold the other nodes and the leaf slots.
  EXPECT_GE(uint64_t(w.leafSlots) * kWideLeafSlotTriangles, uint64_t(tris.size()));
  uint32_t binaryLeafSlots = 0;
  for (const gpu::BvhNode& n : binary.nodes)
    binaryLeafSlots += wideLeafSlots(n.triCount);
  EXPECT_LE(w.leafSlots, binaryLeafSlots);
  const uint32_t binaryInterior = binary.stats.nodeCount - binary.stats.leafCount;
  if (!tris.empty()) {
    EXPECT_LE(wide.nodes.size(), binaryInterior + binary.stats.leafCount / 2 + 1);
    EXPECT_GE(wide.nodes.size() * RL_BVH_WIDTH, w.leafSlots + wide.nodes.size() - 1);
  }
}

struct Ray {
  glm::vec3 origin, dir;
};

// Camera rays of every view, rays from points on triangles in random directions (the later bounces), and
// axis-aligned rays (zero direction components: the slab test's safe inverse).
std::vector<Ray> testRays(const Scene& scene, uint32_t perView, uint32_t secondary, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<Ray> rays;
  for (const Viewpoint& v : scene.viewpoints) {
    const gpu::GpuCamera c = makeGpuCamera(v, 512, 256);
    for (uint32_t i = 0; i < perView; ++i) {
      const glm::vec2 ndc(2.0f * u(rng) - 1.0f, 1.0f - 2.0f * u(rng));
      rays.push_back({c.position, cameraRayDirection(c, ndc)});
    }
  }
  std::uniform_int_distribution<size_t> pick(0, scene.triangles.size() - 1);
  std::normal_distribution<float> g;
  for (uint32_t i = 0; i < secondary; ++i) {
    const Triangle& t = scene.triangles[pick(rng)];
    float a = u(rng), b = u(rng);
    if (a + b > 1.0f) a = 1.0f - a, b = 1.0f - b;
    glm::vec3 dir(g(rng), g(rng), g(rng));
    if (i % 16 == 0) dir = glm::vec3(0.0f), dir[i / 16 % 3] = (i / 48 % 2) ? 1.0f : -1.0f;
    if (glm::length(dir) < 1e-6f) dir = glm::vec3(0, 1, 0);
    const glm::vec3 p = t.v[0] + a * (t.v[1] - t.v[0]) + b * (t.v[2] - t.v[0]);
    rays.push_back({p + 1e-3f * glm::normalize(dir), glm::normalize(dir)});
  }
  return rays;
}

struct Agreement {
  uint64_t rays = 0, hits = 0, ties = 0, binaryMisses = 0, checkedByAll = 0, axisAlignedWideMisses = 0;
  uint64_t closestMismatches = 0, anyHitMismatches = 0;
  double binarySteps = 0, wideSteps = 0;
  // Fetches per ray (CpuHit's counts) and the CPU twins' time, for the closest-hit traversals.
  double binaryNodes = 0, binaryTriangles = 0, wideNodes = 0, wideLeafRecords = 0, wideTriangles = 0;
  double binaryNs = 0, wideNs = 0;
};

bool sameHitT(const CpuHit& a, const CpuHit& b) {
  if (a.t < 0.0f || b.t < 0.0f) return a.t < 0.0f && b.t < 0.0f;
  return std::abs(a.t - b.t) <= 1e-5f * std::max(1.0f, a.t);
}

// Closest hits: the wide tree's equals the binary tree's (the same triangle tests in float: the same t bit for
// bit when the same triangle wins; another triangle only at t equal within 1e-5 relative, a tie). Where they
// differ, and for every `allEvery`-th ray, the reference is every triangle tested (intersectAllCpu): the
// binary tree misses hits on its exact boxes' faces that axis-aligned rays graze, so the wide one must match
// the reference there. Rays with a zero direction component lying exactly in a box face's plane miss that
// box in both layouts (the slab test's 0 * 1e20): for them the wide tree must only be no worse than the binary
// one (its boxes are never smaller). Any hit (shadow rays): occluded with tMax = infinity iff the closest hit exists, with
// tMax just beyond it (1.001 t) always, and with tMax just before it (0.999 t) only where the reference
// finds a triangle there too (a tie).
Agreement compare(const Scene& scene, const Bvh& binary, const BvhWide& wide, const std::vector<Ray>& rays,
                  uint32_t allEvery) {
  const std::vector<gpu::GpuTriangle> tris = bvhOrderTriangles(scene.triangles, binary.triangleOrder);
  Agreement a;
  for (const Ray& r : rays) {
    const auto t0 = std::chrono::steady_clock::now();
    const CpuHit b = traverseBinaryCpu(binary.nodes, tris, r.origin, r.dir, 1e30f, false);
    const auto t1 = std::chrono::steady_clock::now();
    const CpuHit w = traverseWideCpu(wide, tris, r.origin, r.dir, 1e30f, false);
    const auto t2 = std::chrono::steady_clock::now();
    a.binaryNs += std::chrono::duration<double, std::nano>(t1 - t0).count();
    a.wideNs += std::chrono::duration<double, std::nano>(t2 - t1).count();
    a.binarySteps += b.steps;
    a.wideSteps += w.steps;
    a.binaryNodes += b.nodeVisits;
    a.binaryTriangles += b.triangleTests;
    a.wideNodes += w.nodeVisits;
    a.wideLeafRecords += w.leafRecords;
    a.wideTriangles += w.triangleTests;
    CpuHit reference = b;
    const bool agree = sameHitT(b, w) && (b.triangle == w.triangle ? b.t == w.t : true);
    if (!agree || a.rays % allEvery == 0) {
      ++a.checkedByAll;
      reference = intersectAllCpu(tris, r.origin, r.dir, 1e30f);
      if (!sameHitT(reference, b)) ++a.binaryMisses;
    }
    ++a.rays;
    const bool wideMatches = sameHitT(reference, w) && (reference.triangle != w.triangle || reference.t == w.t);
    const bool axisAligned = r.dir.x == 0.0f || r.dir.y == 0.0f || r.dir.z == 0.0f;
    if (!wideMatches && axisAligned && !sameHitT(reference, b)) {
      ++a.axisAlignedWideMisses;
      continue;
    }
    if (!wideMatches) {
      if (++a.closestMismatches <= 5)
        std::printf("closest: reference t %g (triangle %u), wide %g (%u); origin (%g, %g, %g) direction (%g, %g, %g)\n",
                    reference.t, reference.triangle, w.t, w.triangle, r.origin.x, r.origin.y, r.origin.z, r.dir.x,
                    r.dir.y, r.dir.z);
      continue;
    }
    if (w.t < 0.0f) {
      if (traverseWideCpu(wide, tris, r.origin, r.dir, 1e30f, true).t > 0.0f) ++a.anyHitMismatches;
      continue;
    }
    ++a.hits;
    if (reference.triangle != w.triangle) ++a.ties;
    if (!(traverseWideCpu(wide, tris, r.origin, r.dir, 1e30f, true).t > 0.0f)) ++a.anyHitMismatches;
    if (!(traverseWideCpu(wide, tris, r.origin, r.dir, 1.001f * w.t, true).t > 0.0f)) ++a.anyHitMismatches;
    if (traverseWideCpu(wide, tris, r.origin, r.dir, 0.999f * w.t, true).t > 0.0f &&
        !(intersectAllCpu(tris, r.origin, r.dir, 0.999f * w.t).t > 0.0f))
      ++a.anyHitMismatches;
  }
  return a;
}

void expectAgreement(const Agreement& a, const char* what) {
  std::printf("%s: %llu rays, %llu hit, %llu ties, %llu checked against every triangle, %llu the binary tree "
              "missed (%llu of them the wide one too, all axis-aligned); mean steps binary %.2f, wide %.2f\n",
              what, (unsigned long long)a.rays, (unsigned long long)a.hits, (unsigned long long)a.ties,
              (unsigned long long)a.checkedByAll, (unsigned long long)a.binaryMisses,
              (unsigned long long)a.axisAlignedWideMisses, a.binarySteps / double(a.rays),
              a.wideSteps / double(a.rays));
  std::printf("%s: per ray, wide %.2f nodes + %.2f leaf records + %.2f triangles (%.0f bytes), binary %.2f nodes + "
              "%.2f triangles (%.0f bytes); CPU twin %.0f ns a ray wide, %.0f binary\n",
              what, a.wideNodes / double(a.rays), a.wideLeafRecords / double(a.rays), a.wideTriangles / double(a.rays),
              (80.0 * a.wideNodes + 8.0 * a.wideLeafRecords + 48.0 * a.wideTriangles) / double(a.rays),
              a.binaryNodes / double(a.rays), a.binaryTriangles / double(a.rays),
              (64.0 * a.binaryNodes + 48.0 * a.binaryTriangles) / double(a.rays), a.wideNs / double(a.rays),
              a.binaryNs / double(a.rays));
  EXPECT_EQ(a.closestMismatches, 0u) << what;
  EXPECT_EQ(a.anyHitMismatches, 0u) << what;
  EXPECT_GT(a.hits, a.rays / 4) << what << ": the rays must mostly hit something to test anything";
  EXPECT_GT(a.checkedByAll, a.rays / 100) << what;
  EXPECT_LE(a.axisAlignedWideMisses, a.binaryMisses) << what;
}

// Both collapses (Settings::wideCollapse), each test of the tree and its traversal for each.
std::string named(const char* what, WideCollapse how) { return std::string(what) + " (" + toString(how) + ")"; }

// Both collapses of `scene`: each tree's structure and its traversal against the binary one's, and the SAH
// collapse's cost, optimal on exact boxes, still no worse than greedy's on the quantized ones.
void checkBothCollapses(const char* what, const Scene& scene, uint32_t perView, uint32_t secondary, uint32_t seed,
                        uint32_t allEvery) {
  std::map<WideCollapse, double> cost;
  for (WideCollapse how : allValues<WideCollapse>()) {
    Bvh binary = buildBvh(scene.triangles);
    const BvhWide wide = collapseBvh(binary, 0, how);
    checkStructure(scene.triangles, binary, wide);
    cost[how] = wideSahCost(wide, binary);
    std::printf("%s (%s): %zu triangles, binary %u nodes, wide %u nodes + %u leaf slots, %.1f tree bytes/triangle, "
                "collapse %.0f ms, wide SAH cost %.2f\n", what, toString(how).c_str(), scene.triangles.size(),
                binary.stats.nodeCount, wide.stats.nodeCount, wide.stats.leafCount,
                double(wide.stats.treeBytes()) / double(scene.triangles.size()), wide.stats.buildMs, cost[how]);
    expectAgreement(compare(scene, binary, wide, testRays(scene, perView, secondary, seed), allEvery),
                    named(what, how).c_str());
  }
  EXPECT_LE(cost.at(WideCollapse::Sah), cost.at(WideCollapse::Greedy)) << what;
}

TEST(BvhWide, TempleStructureAndTraversal) { checkBothCollapses("temple", makeTemple(), 4000, 20000, 7, 10); }

TEST(BvhWide, RandomAndIdenticalTriangles) {
  Scene random;
  random.triangles = randomTriangles(3000, 11);
  random.viewpoints.push_back({"outside", {0, 0, 40}, {0, 0, 0}});
  random.viewpoints.push_back({"inside", {0.5f, 0.2f, 0.1f}, {3, 1, -2}});
  // Many triangles in one place: one big leaf (SAH cannot split them), a root with one leaf child or a few.
  Scene same;
  same.triangles.assign(300, random.triangles[0]);
  same.viewpoints.push_back({"front", 0.5f * (same.triangles[0].v[0] + same.triangles[0].v[1]) + glm::vec3(0, 0, 30),
                             same.triangles[0].v[2]});
  for (WideCollapse how : allValues<WideCollapse>()) {
    Bvh binary = buildBvh(random.triangles);
    const BvhWide wide = collapseBvh(binary, 0, how);
    checkStructure(random.triangles, binary, wide);
    expectAgreement(compare(random, binary, wide, testRays(random, 3000, 5000, 5), 10),
                    named("random triangles", how).c_str());
    Bvh sameBinary = buildBvh(same.triangles);
    const BvhWide sameWide = collapseBvh(sameBinary, 0, how);
    checkStructure(same.triangles, sameBinary, sameWide);
  }
}

// The SAH's choice where it is plain: four far clusters of 8 overlapping triangles, 32 in all (a node's leaf
// budget). As leaf slots of the root they cost 32 * 0.3 * a cluster's area; a wide node for any of them costs
// its area more, for nothing (its children's boxes overlap, as big). So the whole tree is the root, whatever
// leaves Embree made: with single-triangle leaves, the collapse that opened the largest subtrees until 8 made
// 9 nodes of it.
TEST(BvhWide, SahKeepsOverlappingClustersAsLeaves) {
  std::vector<Triangle> tris;
  for (float x : {0.0f, 100.0f, 200.0f, 300.0f})
    for (int i = 0; i < 8; ++i) {
      Triangle t;
      const glm::vec3 o(x + 1e-3f * float(i), 1e-3f * float(i % 3), 0.0f);
      t.v[0] = o, t.v[1] = o + glm::vec3(1, 0, 0), t.v[2] = o + glm::vec3(0, 1, 0.5f);
      tris.push_back(t);
    }
  for (uint32_t maxLeaf : {1u, 2u, 8u}) {
    Bvh binary = buildBvh(tris, maxLeaf);
    Bvh greedyBinary = binary;
    const BvhWide wide = collapseBvh(binary, 0, WideCollapse::Sah);
    checkStructure(tris, binary, wide);
    EXPECT_EQ(wide.nodes.size(), 1u) << "leaf " << maxLeaf;
    const BvhWide greedy = collapseBvh(greedyBinary, 0, WideCollapse::Greedy);
    if (maxLeaf == 1) {
      EXPECT_EQ(greedy.nodes.size(), 9u);
    }
    EXPECT_LE(wideSahCost(wide, binary), wideSahCost(greedy, greedyBinary)) << "leaf " << maxLeaf;
  }
}

TEST(BvhWide, OneTriangleAndNone) {
  Scene one;
  one.triangles.resize(1);
  one.triangles[0].v[1] = {1, 0, 0};
  one.triangles[0].v[2] = {0, 1, 0};
  for (WideCollapse how : allValues<WideCollapse>()) {
    SCOPED_TRACE(toString(how));
    Bvh binary = buildBvh(one.triangles);  // a root that is a leaf
    const BvhWide wide = collapseBvh(binary, 0, how);
    checkStructure(one.triangles, binary, wide);
    ASSERT_EQ(wide.nodes.size(), 1u);
    ASSERT_EQ(wide.stats.leafCount, 1u);
    // The SAH cost: the root (1) and its one triangle in a slot as big as the root, to a quantization step (0.3).
    EXPECT_NEAR(wideSahCost(wide, binary), 1.3, 0.01);
    const std::vector<gpu::GpuTriangle> tris = bvhOrderTriangles(one.triangles, binary.triangleOrder);
    EXPECT_NEAR(traverseWideCpu(wide, tris, {0.2f, 0.2f, 1}, {0, 0, -1}, 1e30f, false).t, 1.0f, 1e-6f);
    EXPECT_LT(traverseWideCpu(wide, tris, {2, 2, 1}, {0, 0, -1}, 1e30f, false).t, 0.0f);
    // No triangles: a root without children, every ray misses after one step.
    Bvh none = buildBvh({});
    const BvhWide empty = collapseBvh(none, 0, how);
    EXPECT_EQ(empty.nodes.size(), 1u);
    EXPECT_EQ(empty.stats.leafCount, 0u);
    EXPECT_EQ(wideSahCost(empty, none), 0.0);
    const CpuHit miss = traverseWideCpu(empty, {}, {0, 0, 0}, {0, 0, 1}, 1e30f, false);
    EXPECT_LT(miss.t, 0.0f);
    EXPECT_EQ(miss.steps, 1u);
  }
}

void expectSameCollapse(const std::vector<Triangle>& tris, uint32_t maxLeaf, const std::string& what) {
  const Bvh built = buildBvh(tris, maxLeaf);
  for (WideCollapse how : allValues<WideCollapse>()) {
    Bvh one = built;
    const BvhWide wideOne = collapseBvh(one, 1, how);
    for (uint32_t threads : {2u, 5u, 16u, 0u}) {
      const std::string with = what + ", " + toString(how) + ", leaf " + std::to_string(maxLeaf) + ", " +
                               std::to_string(threads) + " threads";
      Bvh many = built;
      const BvhWide wideMany = collapseBvh(many, threads, how);
      ASSERT_EQ(wideMany.nodes.size(), wideOne.nodes.size()) << with;
      EXPECT_EQ(std::memcmp(wideMany.nodes.data(), wideOne.nodes.data(),
                            wideOne.nodes.size() * sizeof(gpu::BvhWideNode)), 0) << with;
      EXPECT_EQ(std::memcmp(many.nodes.data(), one.nodes.data(), one.nodes.size() * sizeof(gpu::BvhNode)), 0) << with;
      EXPECT_EQ(many.triangleOrder, one.triangleOrder) << with;
      EXPECT_EQ(wideMany.stats.nodeCount, wideOne.stats.nodeCount) << with;
      EXPECT_EQ(wideMany.stats.leafCount, wideOne.stats.leafCount) << with;
      EXPECT_EQ(wideMany.stats.maxDepth, wideOne.stats.maxDepth) << with;
    }
  }
}

// The collapse on several threads (subtrees collapsed on their own, then moved into place) gives the same wide
// nodes, leaf order and stats, bit for bit, as the one recursion on one thread; with leaves up to 32 triangles
// too (several slots a leaf) and single-triangle leaves (blocks from offset 1).
TEST(BvhWide, SameTreeOnAnyThreadCount) {
  const std::vector<Triangle> random = randomTriangles(20000, 9);
  const std::vector<Triangle> temple = makeTemple().triangles;
  for (uint32_t leaf : {1u, 8u, 32u}) {
    expectSameCollapse(temple, leaf, "temple");
    expectSameCollapse(random, leaf, "random");
  }
  expectSameCollapse(std::vector<Triangle>(3000, random[0]), 8, "identical");
  expectSameCollapse(std::vector<Triangle>(1, random[0]), 8, "one");
  expectSameCollapse({}, 8, "none");
}

TEST(BvhWide, Sponza) {
  const std::string path = RAYLAB_SOURCE_DIR "/../shared/scenes/Sponza/Sponza.gltf";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "no Sponza at " << path;
  checkBothCollapses("Sponza", loadGltf(path), 2000, 10000, 3, 100);
}

}  // namespace
}  // namespace raylab
