// What `raylab tracebench --fetches` counts (app/tracebench/warp_fetches.h): the reads of the pair-node traversal's
// CPU twin (traversePairsCpu, itself checked against the shader ray by ray in
// tests/gpu/bvh/test_embree_hits.cpp), summed lane by lane, warp by warp and window by window. Checked here against
// plain sets of the logged reads, and against what must hold: a warp of one ray repeated reads each thing once,
// and sorting rays by where they go makes a warp's lanes share more of their reads.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <set>
#include <stdexcept>

#include "app/tracebench/warp_fetches.h"
#include "renderer/bvh/bvh_leaf_records.h"
#include "renderer/bvh/bvh_pairs.h"
#include "renderer/bvh/bvh_traverse_cpu.h"
#include "scenes/procedural.h"

namespace raylab {
namespace {

// The plain binary tree as the GPU reads it (GpuSceneData's without a device).
HostPairTree pairTreeOf(const Scene& scene) {
  const Bvh bvh = buildBvh(scene.triangles);
  return {pairNodes(bvh), leafRecords(scene.triangles, bvh.triangleOrder, bvh.triangleOrder)};
}

// Rays from random points inside the scene's box in random directions; every other one bounded.
RaySet randomRays(const Scene& scene, uint32_t count, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::normal_distribution<float> gauss;
  const Bounds b = scene.bounds();
  RaySet rays;
  for (uint32_t i = 0; i < count; ++i) {
    const glm::vec3 o = b.min + glm::vec3(unit(rng), unit(rng), unit(rng)) * b.extent();
    const glm::vec3 d = glm::normalize(glm::vec3(gauss(rng), gauss(rng), gauss(rng)));
    rays.add(o, d, i % 2 ? unit(rng) * glm::length(b.extent()) : 1e30f);
  }
  return rays;
}

PairFetchLog logOf(const HostPairTree& tree, const RaySet& rays, uint32_t i, bool anyHit, CpuHit* hit = nullptr) {
  PairFetchLog log;
  const CpuHit h = traversePairsCpu(tree.nodes, tree.entries, glm::vec3(rays.origins[i]),
                                    glm::vec3(rays.directions[i]), rays.directions[i].w, anyHit, &log);
  if (hit) *hit = h;
  return log;
}

TEST(WarpFetches, TheLogHoldsEveryReadTheCountsName) {
  const Scene scene = makeTemple();
  const HostPairTree tree = pairTreeOf(scene);
  const RaySet rays = randomRays(scene, 500, 1);
  uint32_t leaves = 0;
  for (uint32_t i = 0; i < rays.size(); ++i)
    for (bool anyHit : {false, true}) {
      CpuHit hit;
      const PairFetchLog log = logOf(tree, rays, i, anyHit, &hit);
      EXPECT_EQ(log.nodes().size(), hit.nodeVisits);
      EXPECT_EQ(log.entries().size(), hit.triangleTests);
      EXPECT_EQ(log.steps.size(), hit.steps);
      EXPECT_EQ(std::count_if(log.steps.begin(), log.steps.end(), [](uint32_t w) { return w < RL_LEAF_TAG; }),
                hit.nodeVisits);
      EXPECT_GE(hit.steps, hit.nodeVisits);  // the rest are leaves
      leaves += hit.steps - hit.nodeVisits;
      for (uint32_t n : log.nodes()) EXPECT_LT(n, tree.nodes.size());
      for (uint32_t e : log.entries()) EXPECT_LT(e, tree.entries.size());
    }
  EXPECT_GT(leaves, rays.size()) << "the rays reached too few leaves to prove anything";
}

// The twin over the pair nodes finds what the twin over the BvhNode tree they are made from finds: the same
// loop, a node's two boxes tested in the parent rather than in the children. The steps may differ where a box's
// entry equals the hit's distance (a triangle on a face of a neighbouring box, common in the temple's axis-aligned
// stone): the two slab forms, (b - o) / d and b / d - o / d, round that tie either way. Seen: 51 of 2,000 rays.
TEST(WarpFetches, PairTwinFindsWhatTheBinaryTwinFinds) {
  const Scene scene = makeTemple();
  const Bvh bvh = buildBvh(scene.triangles);
  const HostPairTree tree = pairTreeOf(scene);
  const std::vector<gpu::GpuTriangle> tris = bvhOrderTriangles(scene.triangles, bvh.triangleOrder);
  const RaySet rays = randomRays(scene, 2000, 2);
  uint32_t differ = 0, stepsDiffer = 0, hits = 0;
  uint64_t pairSteps = 0, binarySteps = 0;
  for (uint32_t i = 0; i < rays.size(); ++i) {
    const glm::vec3 o(rays.origins[i]), d(rays.directions[i]);
    for (bool anyHit : {false, true}) {
      const CpuHit p = traversePairsCpu(tree.nodes, tree.entries, o, d, rays.directions[i].w, anyHit);
      const CpuHit b = traverseBinaryCpu(bvh.nodes, tris, o, d, rays.directions[i].w, anyHit);
      differ += (p.t > 0.0f) != (b.t > 0.0f) ||
                (!anyHit && (p.triangle != b.triangle || std::abs(p.t - b.t) > 1e-5f * (1.0f + b.t)));
      if (anyHit) continue;
      stepsDiffer += p.steps != b.steps;
      pairSteps += p.steps, binarySteps += b.steps;
      hits += b.t > 0.0f;
    }
  }
  EXPECT_LE(differ, rays.size() / 500);  // the same tie can hide a hit at tMax: seen 1 of 4,000 traversals
  EXPECT_LE(stepsDiffer, rays.size() / 20);
  EXPECT_NEAR(double(pairSteps) / double(binarySteps), 1.0, 0.02);
  EXPECT_GT(hits, rays.size() / 3);
}

// countFetches against sets of the logged reads: each lane's reads, each warp's distinct ones, each window's
// distinct bytes, on a set of several windows with a tail; and the lockstep loads: a set for each iteration k of
// a warp (its lanes' step k) and each entry j of the leaves met there.
TEST(WarpFetches, CountsAreThoseOfPlainSets) {
  const Scene scene = makeTemple();
  const HostPairTree tree = pairTreeOf(scene);
  const RaySet rays = randomRays(scene, 3 * 256 + 40, 3);
  const uint32_t window = 256;
  for (bool anyHit : {false, true}) {
    uint64_t nodes = 0, entries = 0, warpNodes = 0, warpEntries = 0, steps = 0;
    double windowBytes = 0;
    std::set<uint32_t> wn, we, gn, ge;
    for (uint32_t i = 0; i < rays.size(); ++i) {
      if (i % kWarpSize == 0) warpNodes += wn.size(), warpEntries += we.size(), wn.clear(), we.clear();
      if (i % window == 0) {
        if (i > 0) windowBytes += double(gn.size()) * kPairNodeBytes + double(ge.size()) * kLeafEntryBytes;
        gn.clear(), ge.clear();
      }
      CpuHit hit;
      const PairFetchLog log = logOf(tree, rays, i, anyHit, &hit);
      const std::vector<uint32_t> laneNodes = log.nodes(), laneEntries = log.entries();
      steps += hit.steps, nodes += laneNodes.size(), entries += laneEntries.size();
      wn.insert(laneNodes.begin(), laneNodes.end()), gn.insert(laneNodes.begin(), laneNodes.end());
      we.insert(laneEntries.begin(), laneEntries.end()), ge.insert(laneEntries.begin(), laneEntries.end());
    }
    warpNodes += wn.size(), warpEntries += we.size();  // the last warp; the tail's window is left out
    uint64_t requestNodes = 0, requestEntries = 0;
    for (uint32_t w = 0; w * kWarpSize < rays.size(); ++w) {
      std::vector<PairFetchLog> lanes;
      for (uint32_t i = w * kWarpSize; i < std::min<uint32_t>(rays.size(), (w + 1) * kWarpSize); ++i)
        lanes.push_back(logOf(tree, rays, i, anyHit));
      std::map<uint32_t, std::set<uint32_t>> nodesAt;
      std::map<std::pair<uint32_t, uint32_t>, std::set<uint32_t>> entriesAt;
      for (const PairFetchLog& lane : lanes)
        for (uint32_t k = 0; k < lane.steps.size(); ++k) {
          const uint32_t word = lane.steps[k];
          if (word < RL_LEAF_TAG) {
            nodesAt[k].insert(word);
            continue;
          }
          for (uint32_t j = 0; j < RL_LEAF_COUNT(word); ++j) entriesAt[{k, j}].insert(RL_LEAF_FIRST(word) + j);
        }
      for (const auto& [k, set] : nodesAt) requestNodes += set.size();
      for (const auto& [kj, set] : entriesAt) requestEntries += set.size();
    }
    const double n = rays.size();
    const FetchCounts c = countFetches(tree, rays, anyHit, window);
    EXPECT_DOUBLE_EQ(c.requestNodesPerRay, requestNodes / n);
    EXPECT_DOUBLE_EQ(c.requestEntriesPerRay, requestEntries / n);
    // A warp's loads lie between its distinct reads (each loaded once) and its lanes' reads (none shared).
    EXPECT_GT(c.requestNodesPerRay, c.warpNodesPerRay);
    EXPECT_LT(c.requestNodesPerRay, c.nodesPerRay);
    EXPECT_DOUBLE_EQ(c.meanSteps, steps / n);
    EXPECT_DOUBLE_EQ(c.nodesPerRay, nodes / n);
    EXPECT_DOUBLE_EQ(c.entriesPerRay, entries / n);
    EXPECT_DOUBLE_EQ(c.warpNodesPerRay, warpNodes / n);
    EXPECT_DOUBLE_EQ(c.warpEntriesPerRay, warpEntries / n);
    EXPECT_NEAR(c.windowMegabytes, windowBytes / 3 * 1e-6, 1e-12);
    EXPECT_LT(c.warpNodesPerRay, c.nodesPerRay);  // some reads are shared even among random rays
  }
}

// A warp of one ray repeated reads each thing once: its distinct reads are a lane's, a 32nd a ray. A window
// smaller than the set is a window of the set alone, and one of fewer rays than a warp is a warp.
TEST(WarpFetches, AWarpOfOneRayReadsEachThingOnce) {
  const Scene scene = makeTemple();
  const HostPairTree tree = pairTreeOf(scene);
  const RaySet some = randomRays(scene, 3, 4);
  RaySet repeated;
  for (uint32_t r = 0; r < some.size(); ++r)
    for (uint32_t lane = 0; lane < kWarpSize; ++lane)
      repeated.add(glm::vec3(some.origins[r]), glm::vec3(some.directions[r]), some.directions[r].w);
  const FetchCounts c = countFetches(tree, repeated, false, 1);
  EXPECT_GT(c.nodesPerRay, 1.0);
  EXPECT_DOUBLE_EQ(c.warpNodesPerRay * kWarpSize, c.nodesPerRay);
  EXPECT_DOUBLE_EQ(c.warpEntriesPerRay * kWarpSize, c.entriesPerRay);
  EXPECT_DOUBLE_EQ(c.requestNodesPerRay, c.warpNodesPerRay);  // the lanes walk in step: one load a read
  EXPECT_DOUBLE_EQ(c.requestEntriesPerRay, c.warpEntriesPerRay);
  // Windows of one warp (1 is rounded up to a warp): a window's bytes are its warp's distinct reads.
  EXPECT_NEAR(c.windowMegabytes * 1e6,
              (c.warpNodesPerRay * kPairNodeBytes + c.warpEntriesPerRay * kLeafEntryBytes) * kWarpSize, 1e-6);
  EXPECT_EQ(countFetches(tree, RaySet{}, false).nodesPerRay, 0.0);
  EXPECT_THROW(countFetches(tree, some, false, 0), std::invalid_argument);
}

// Rays sorted by their origin cell and direction read fewer distinct things a warp than the same rays shuffled,
// the same reads lane by lane.
TEST(WarpFetches, RaysInOrderShareMoreReadsThanShuffled) {
  const Scene scene = makeTemple();
  const HostPairTree tree = pairTreeOf(scene);
  RaySet shuffled = randomRays(scene, 4096, 5);
  std::vector<uint32_t> order(shuffled.size());
  for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  const Bounds b = scene.bounds();
  auto cell = [&](uint32_t i) {
    const glm::ivec3 c = glm::ivec3((glm::vec3(shuffled.origins[i]) - b.min) / b.extent() * 4.0f);
    const glm::vec3 d(shuffled.directions[i]);
    return ((c.x * 5 + c.y) * 5 + c.z) * 8 + (d.x < 0) * 4 + (d.y < 0) * 2 + (d.z < 0);
  };
  std::stable_sort(order.begin(), order.end(), [&](uint32_t x, uint32_t y) { return cell(x) < cell(y); });
  RaySet sorted;
  for (uint32_t i : order)
    sorted.add(glm::vec3(shuffled.origins[i]), glm::vec3(shuffled.directions[i]), shuffled.directions[i].w);
  const FetchCounts s = countFetches(tree, sorted, false), u = countFetches(tree, shuffled, false);
  EXPECT_DOUBLE_EQ(s.nodesPerRay, u.nodesPerRay);
  EXPECT_DOUBLE_EQ(s.windowMegabytes, u.windowMegabytes);  // one window: the whole set either way
  EXPECT_LT(s.warpNodesPerRay, 0.8 * u.warpNodesPerRay);
  EXPECT_LT(s.warpEntriesPerRay, u.warpEntriesPerRay);
}

}  // namespace
}  // namespace raylab
