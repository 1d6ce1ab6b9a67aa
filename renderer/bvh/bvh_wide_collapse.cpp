// collapseBvh (renderer/bvh/bvh_wide.h): the wide nodes in depth-first order, each node's interior children
// consecutive, each node's leaf triangles one block in front of its children's.
//
// One recursion would place every node after the ones before it. On several threads, the top of the tree is
// planned here and the subtrees below it are collapsed on their own, into arrays of their own, as if each were
// the whole tree; then the top is placed, each subtree gets the place the one recursion would have given it,
// and its nodes move there. A subtree's nodes and triangles are one range in the recursion's arrays (it places
// all of a subtree before going on), and every index in them (childBase, triBase, a leaf's first triangle) is
// its own array's size at some point plus the range's start: the moved subtree has the same bits as the one
// recursion's, with that start added (modulo 2^32, as triBase may be one below the block).
// temple-detail:10000000 on the 16-core H200 host: 3.2 s on one thread, 0.3 s on 16
// (docs/results/bvh-parallel/README.md).
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "renderer/bvh/bvh_wide.h"
#include "renderer/bvh/bvh_wide_plan.h"
#include "renderer/parallel.h"

namespace raylab {
namespace {

// Gives planned node `p` its place, the one step both the recursion and the top's placement take: its interior
// children at nodeCount onwards, its leaf block at triangleCount onwards (both advanced past them), and
// onLeaf(binary leaf, its first triangle) for each leaf in block order. A node without children (the empty
// scene's root) stays all zeros.
template <typename OnLeaf>
gpu::BvhWideNode placeNode(const WideNodePlan& p, const Bvh& binary, uint32_t& nodeCount, uint32_t& triangleCount,
                           const OnLeaf& onLeaf) {
  gpu::BvhWideNode node = p.node;
  if (p.empty) return node;
  node.childBase = nodeCount;
  nodeCount += uint32_t(p.interiors.size());
  node.triBase = triangleCount - p.blockStart;
  for (uint32_t b : p.leaves) {
    onLeaf(b, triangleCount);
    triangleCount += binary.nodes[b].triCount;
  }
  return node;
}

// The recursion, on one binary subtree: node 0 of `nodes` is the subtree's root (its place is its parent's to
// give), the rest are its descendants.
struct SubtreeCollapse {
  const Bvh* binary = nullptr;
  const WideSlotChooser* slots = nullptr;
  uint32_t binaryRoot = 0, depth = 0;
  std::vector<gpu::BvhWideNode> nodes;
  std::vector<uint32_t> order;                             // its leaves' triangles, in the wide tree's order
  std::vector<std::pair<uint32_t, uint32_t>> movedLeaves;  // (binary leaf, its first triangle in `order`)
  uint32_t leafCount = 0, maxDepth = 0;

  void run() {
    nodes.resize(1);
    build(0, binaryRoot, depth);
  }

  void build(uint32_t wideIndex, uint32_t binaryIndex, uint32_t level) {
    if (level >= RL_BVH_STACK) throw std::runtime_error("wide BVH: deeper than the traversal stack");
    maxDepth = std::max(maxDepth, level);
    const WideNodePlan p = planWideNode(*binary, *slots, binaryIndex);
    leafCount += p.leafSlots;
    uint32_t nodeCount = uint32_t(nodes.size()), triangleCount = uint32_t(order.size());
    const gpu::BvhWideNode node = placeNode(p, *binary, nodeCount, triangleCount, [&](uint32_t b, uint32_t first) {
      const gpu::BvhNode& leaf = binary->nodes[b];
      movedLeaves.push_back({b, first});
      order.insert(order.end(), binary->triangleOrder.begin() + leaf.leftOrFirst,
                   binary->triangleOrder.begin() + leaf.leftOrFirst + leaf.triCount);
    });
    nodes.resize(nodeCount);
    nodes[wideIndex] = node;
    for (uint32_t i = 0; i < p.interiors.size(); ++i) build(node.childBase + i, p.interiors[i], level + 1);
  }
};

// The top of the tree: planned nodes whose children are top nodes or subtrees collapsed on their own.
struct TopNode {
  WideNodePlan plan;
  std::vector<int64_t> children;  // in slot order: >= 0 a top node, < 0 the subtree ~child
};

struct ParallelCollapse {
  Bvh& binary;
  const WideSlotChooser& slots;
  uint64_t splitAbove;  // binary subtrees of more triangles than this are split further
  std::vector<TopNode> top;
  std::vector<SubtreeCollapse> subtrees;
  std::vector<uint64_t> subtreeTriangles;  // for running the largest first
  uint32_t leafCount = 0, maxDepth = 0;

  uint32_t plan(uint32_t binaryIndex, uint32_t depth) {
    if (depth >= RL_BVH_STACK) throw std::runtime_error("wide BVH: deeper than the traversal stack");
    maxDepth = std::max(maxDepth, depth);
    const uint32_t index = uint32_t(top.size());
    top.push_back({planWideNode(binary, slots, binaryIndex), {}});
    leafCount += top[index].plan.leafSlots;
    const std::vector<uint32_t> interiors = top[index].plan.interiors;
    for (uint32_t b : interiors) {
      const uint64_t triangles = slots.trianglesUnder(b);
      if (triangles > splitAbove) {
        const uint32_t child = plan(b, depth + 1);  // a statement of its own: plan() may move `top`
        top[index].children.push_back(child);
      } else {
        top[index].children.push_back(~int64_t(subtrees.size()));
        subtrees.push_back({&binary, &slots, b, depth + 1});
        subtreeTriangles.push_back(triangles);
      }
    }
    return index;
  }
};

// Where each part goes: the top nodes at their final index with childBase and triBase set, the top's leaf
// triangles, and each subtree's root slot and the start of its descendants and of its triangles.
struct Placement {
  struct TopLeaf {
    uint32_t binary, first;  // binary leaf, its first triangle in the wide order
  };
  struct SubtreePlace {
    uint32_t rootSlot, nodeBase, triangleBase;
  };
  std::vector<std::pair<uint32_t, gpu::BvhWideNode>> topNodes;
  std::vector<TopLeaf> topLeaves;
  std::vector<SubtreePlace> subtrees;
  uint32_t nodeCount = 1, triangleCount = 0;

  void place(const ParallelCollapse& c, uint32_t topIndex, uint32_t wideIndex) {
    const gpu::BvhWideNode node = placeNode(c.top[topIndex].plan, c.binary, nodeCount, triangleCount,
                                            [&](uint32_t b, uint32_t first) { topLeaves.push_back({b, first}); });
    topNodes.push_back({wideIndex, node});
    for (size_t i = 0; i < c.top[topIndex].children.size(); ++i) {
      const int64_t child = c.top[topIndex].children[i];
      if (child >= 0) {
        place(c, uint32_t(child), node.childBase + uint32_t(i));
        continue;
      }
      const SubtreeCollapse& s = c.subtrees[size_t(~child)];
      subtrees[size_t(~child)] = {node.childBase + uint32_t(i), nodeCount, triangleCount};
      nodeCount += uint32_t(s.nodes.size() - 1);
      triangleCount += uint32_t(s.order.size());
    }
  }
};

// Moves subtree `s` to its place: its root to rootSlot, its descendant i (from 1) to nodeBase + i - 1.
void moveSubtree(SubtreeCollapse& s, const Placement::SubtreePlace& at, BvhWide& out, std::vector<uint32_t>& order,
                 Bvh& binary) {
  for (size_t i = 0; i < s.nodes.size(); ++i) {
    gpu::BvhWideNode n = s.nodes[i];
    if (n.exponents != 0) {  // a node without children (the empty scene's root) keeps its zeros
      n.childBase += at.nodeBase - 1;
      n.triBase += at.triangleBase;
    }
    out.nodes[i == 0 ? at.rootSlot : at.nodeBase + i - 1] = n;
  }
  std::copy(s.order.begin(), s.order.end(), order.begin() + at.triangleBase);
  for (const auto& [b, first] : s.movedLeaves) binary.nodes[b].leftOrFirst = first + at.triangleBase;
  s = SubtreeCollapse{};  // its memory back before the next one's
}

// The top planned, the subtrees collapsed on the threads, largest first (no thread left with a big one at the
// end).
ParallelCollapse collapseParts(Bvh& binary, const WideSlotChooser& slots, uint32_t threads) {
  ParallelCollapse c{binary, slots, binary.triangleOrder.size() / (8 * uint64_t(threads))};
  c.plan(0, 0);
  std::vector<size_t> largestFirst(c.subtrees.size());
  for (size_t i = 0; i < largestFirst.size(); ++i) largestFirst[i] = i;
  std::stable_sort(largestFirst.begin(), largestFirst.end(),
                   [&](size_t a, size_t b) { return c.subtreeTriangles[a] > c.subtreeTriangles[b]; });
  parallelFor(threads, c.subtrees.size(), [&](size_t i) { c.subtrees[largestFirst[i]].run(); });
  for (const SubtreeCollapse& s : c.subtrees) c.leafCount += s.leafCount, c.maxDepth = std::max(c.maxDepth, s.maxDepth);
  return c;
}

void collapseInParallel(Bvh& binary, const WideSlotChooser& slots, BvhWide& wide, uint32_t threads) {
  ParallelCollapse c = collapseParts(binary, slots, threads);
  Placement at;
  at.subtrees.resize(c.subtrees.size());
  at.place(c, 0, 0);
  if (at.triangleCount != binary.triangleOrder.size())
    throw std::runtime_error("wide BVH: its leaves hold another number of triangles than the binary tree's");
  resizeFaultingInParallel(wide.nodes, at.nodeCount, threads);
  std::vector<uint32_t> order;
  resizeFaultingInParallel(order, at.triangleCount, threads);
  for (const auto& [index, node] : at.topNodes) wide.nodes[index] = node;
  for (const Placement::TopLeaf& l : at.topLeaves) {
    const gpu::BvhNode& leaf = binary.nodes[l.binary];
    std::copy_n(binary.triangleOrder.begin() + leaf.leftOrFirst, leaf.triCount, order.begin() + l.first);
  }
  // Every subtree has read what it needed of the binary tree: now its leaves may move.
  for (const Placement::TopLeaf& l : at.topLeaves) binary.nodes[l.binary].leftOrFirst = l.first;
  parallelFor(threads, c.subtrees.size(),
              [&](size_t i) { moveSubtree(c.subtrees[i], at.subtrees[i], wide, order, binary); });
  binary.triangleOrder = std::move(order);
  wide.stats.leafCount = c.leafCount;
  wide.stats.maxDepth = c.maxDepth;
}

// The one recursion: the whole tree as one subtree, already at its place.
void collapseSerially(Bvh& binary, const WideSlotChooser& slots, BvhWide& wide) {
  SubtreeCollapse s{&binary, &slots, 0, 0};
  s.order.reserve(binary.triangleOrder.size());
  s.run();
  if (s.order.size() != binary.triangleOrder.size())
    throw std::runtime_error("wide BVH: its leaves hold another number of triangles than the binary tree's");
  for (const auto& [b, first] : s.movedLeaves) binary.nodes[b].leftOrFirst = first;
  binary.triangleOrder = std::move(s.order);
  wide.nodes = std::move(s.nodes);
  wide.stats.leafCount = s.leafCount;
  wide.stats.maxDepth = s.maxDepth;
}

}  // namespace

BvhWide collapseBvh(Bvh& binary, uint32_t threads, WideCollapse how) {
  const auto start = std::chrono::steady_clock::now();
  BvhWide wide;
  wide.nodes.resize(1);
  if (!binary.nodes.empty()) {
    threads = workerThreads(threads, binary.triangleOrder.size(), 16384);
    const WideSlotChooser slots(binary, how, threads);
    if (threads == 1 || binary.triangleOrder.empty()) {
      collapseSerially(binary, slots, wide);
    } else {
      collapseInParallel(binary, slots, wide, threads);
    }
  }
  wide.stats.nodeCount = uint32_t(wide.nodes.size());
  wide.stats.buildMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return wide;
}

}  // namespace raylab
