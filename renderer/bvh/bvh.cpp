// BVH construction through Embree's rtcBuildBVH (RTC_BUILD_QUALITY_MEDIUM: binned SAH, multi-threaded
// through TBB): Embree decides the splits and leaf sizes; its callbacks build a temporary tree in Embree's
// thread-local memory, which is then flattened into our depth-first layout.
//
// Spatial splits (BvhSplits::Spatial: RTC_BUILD_QUALITY_HIGH with a splitPrimitive callback) put one triangle
// into several leaves, while every consumer of the BVH-order triangle array assumes one entry a triangle: the
// emitter table (one emitter per emissive entry), the rt tracer's bottom-level structure (bvhOrderVertices),
// the wide collapse. So the BVH order stays that of the tree without splits, and a split tree is a second
// tree over it: its leaves' entries (triangleOrder, with repeats) name scene triangles, which GpuSceneData
// maps to their BVH-order index in leaf records of their own (renderer/bvh/bvh_leaf_records.h).
//
// Measured on a shared 2-core Debian 12 machine (raylab_bvh_report, docs/results/embree-bvh/README.md), the
// hand-written single-threaded binned SAH builder this replaces (revision 6b6e6a7) against Embree 3.13.5
// (ae7c3b5): SAH cost (bvh_sah.h, both costs 1), build CPU ms, nodes; the wall time was within the noise of
// the other jobs on 2 cores:
//   temple                  7,380 triangles  28.25 -> 27.44   3.4 ->   2.6 ms     6,491 ->     6,347 nodes
//   Sponza                262,087            77.40 -> 75.19   188 ->   129 ms   262,529 ->   263,283
//   temple-detail:1000000 1,001,040          36.04 -> 33.91   683 ->   583 ms 1,002,327 -> 1,002,031
//
// The phases around rtcBuildBVH run on all cores too (renderer/parallel.h): the primitives in chunks, the
// flattening as subtrees at offsets known from Embree's counts, the arrays' pages faulted in on the threads.
// temple-detail:10000000 on the 16-core H200 host (docs/results/bvh-parallel/README.md, wall, the mean of two
// rounds' medians of 3): primitives 225 -> 31 ms, flattening 330 -> 158 ms, the whole build 1.36 -> 0.78 s,
// most of it now Embree's.
#include "renderer/bvh/bvh.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

#include "renderer/bvh/bvh_presplit.h"
#include "renderer/bvh/bvh_sah.h"
#include "renderer/bvh/embree_device.h"
#include "renderer/parallel.h"

namespace raylab {
namespace {

// The depth Embree may use (kMaxBvhDepth). Embree switches to its fallback "large leaf" splits (halving the
// primitive range) 8 levels before it and fails a build that goes past it; the flattening checks our own depth
// against RL_BVH_STACK.
constexpr uint32_t kEmbreeLeafLimit = RTC_BUILD_MAX_PRIMITIVES_PER_LEAF;
static_assert(kEmbreeLeafLimit <= (1u << RL_LEAF_COUNT_BITS), "a leaf must fit the traversal's leaf word");

// The temporary tree, in memory Embree hands out per thread (rtcThreadLocalAlloc) and frees with the BVH.
// An interior node also counts its subtree (set with its children, which Embree sets once they are complete):
// the flattening places every subtree at its final offsets from these counts, in parallel.
struct EmbreeBuildNode {
  uint32_t leafCount = 0;       // 0: interior
  uint32_t interiorBelow = 0;   // interior: the interior nodes of its subtree, itself included
  union {
    uint32_t* prims = nullptr;  // leaf: the primitive ids (triangle indices)
    uint32_t trianglesBelow;    // interior: the triangles of its subtree's leaves
  };
  EmbreeBuildNode* children[2] = {nullptr, nullptr};
  RTCBounds childBounds[2];
};

uint32_t interiorIn(const EmbreeBuildNode* n) { return n && n->leafCount == 0 ? n->interiorBelow : 0; }
uint32_t trianglesIn(const EmbreeBuildNode* n) { return !n ? 0 : n->leafCount > 0 ? n->leafCount : n->trianglesBelow; }

void* embreeCreateNode(RTCThreadLocalAllocator alloc, unsigned int childCount, void*) {
  if (childCount != 2) return nullptr;  // maxBranchingFactor is 2; anything else would be a broken build
  auto* n = new (rtcThreadLocalAlloc(alloc, sizeof(EmbreeBuildNode), 16)) EmbreeBuildNode();
  n->trianglesBelow = 0;
  return n;
}

void embreeSetChildren(void* node, void** children, unsigned int childCount, void*) {
  auto* n = static_cast<EmbreeBuildNode*>(node);
  for (unsigned int i = 0; i < childCount && i < 2; ++i) n->children[i] = static_cast<EmbreeBuildNode*>(children[i]);
  n->interiorBelow = 1 + interiorIn(n->children[0]) + interiorIn(n->children[1]);
  n->trianglesBelow = trianglesIn(n->children[0]) + trianglesIn(n->children[1]);
}

void embreeSetBounds(void* node, const RTCBounds** bounds, unsigned int childCount, void*) {
  auto* n = static_cast<EmbreeBuildNode*>(node);
  for (unsigned int i = 0; i < childCount && i < 2; ++i) n->childBounds[i] = *bounds[i];
}

void* embreeCreateLeaf(RTCThreadLocalAllocator alloc, const RTCBuildPrimitive* prims, size_t count, void*) {
  auto* n = new (rtcThreadLocalAlloc(alloc, sizeof(EmbreeBuildNode), 16)) EmbreeBuildNode();
  n->prims = static_cast<uint32_t*>(rtcThreadLocalAlloc(alloc, sizeof(uint32_t) * std::max<size_t>(count, 1), 4));
  // Two pieces of one presplit triangle (bvh_presplit.h) may meet in a leaf: it holds the triangle once.
  uint32_t kept = 0;
  for (size_t i = 0; i < count; ++i)
    if (std::find(n->prims, n->prims + kept, prims[i].primID) == n->prims + kept) n->prims[kept++] = prims[i].primID;
  n->leafCount = kept;
  return n;
}

bool finite(const Triangle& t) {
  for (const glm::vec3& v : t.v)  // checked per vertex: glm::min would drop a NaN
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) return false;
  return true;
}

RTCBuildPrimitive primitiveOf(const Triangle& t, uint32_t index) {
  glm::vec3 lo = glm::min(t.v[0], glm::min(t.v[1], t.v[2]));
  glm::vec3 hi = glm::max(t.v[0], glm::max(t.v[1], t.v[2]));
  RTCBuildPrimitive p;
  p.lower_x = lo.x, p.lower_y = lo.y, p.lower_z = lo.z, p.geomID = 0;
  p.upper_x = hi.x, p.upper_y = hi.y, p.upper_z = hi.z, p.primID = index;
  return p;
}

// One chunk of the primitives: its triangles' boxes and their union, or the first triangle with a non-finite
// vertex.
struct PrimitiveChunk {
  glm::vec3 lo{std::numeric_limits<float>::max()}, hi{-std::numeric_limits<float>::max()};
  size_t firstBad = std::numeric_limits<size_t>::max();

  void fill(const std::vector<Triangle>& triangles, size_t begin, size_t end, RTCBuildPrimitive* out) {
    for (size_t i = begin; i < end; ++i) {
      if (!finite(triangles[i])) {
        firstBad = i;
        return;
      }
      out[i] = primitiveOf(triangles[i], static_cast<uint32_t>(i));
      lo = glm::min(lo, glm::vec3(out[i].lower_x, out[i].lower_y, out[i].lower_z));
      hi = glm::max(hi, glm::vec3(out[i].upper_x, out[i].upper_y, out[i].upper_z));
    }
  }
};

// Fills `out` with every triangle's box, in chunks on `threads` threads, and sets the scene's box. The chunks'
// boxes are merged in chunk order (glm::min keeps the earlier of equal values, as one loop would: the same
// bits), and the error names the lowest bad triangle, whichever chunk finished first. A few chunks a thread
// share the work out on a loaded machine.
void fillPrimitives(const std::vector<Triangle>& triangles, uint32_t threads, RTCBuildPrimitive* out,
                    glm::vec3& lo, glm::vec3& hi) {
  const size_t chunkCount = threads == 1 ? 1 : 4 * size_t(threads);
  const size_t chunkSize = (triangles.size() + chunkCount - 1) / chunkCount;
  std::vector<PrimitiveChunk> chunks(chunkCount);
  parallelFor(threads, chunkCount, [&](size_t c) {
    chunks[c].fill(triangles, std::min(c * chunkSize, triangles.size()),
                   std::min((c + 1) * chunkSize, triangles.size()), out);
  });
  for (const PrimitiveChunk& c : chunks) {
    if (c.firstBad != std::numeric_limits<size_t>::max())
      throw std::invalid_argument("buildBvh: triangle " + std::to_string(c.firstBad) + " has a non-finite vertex");
    lo = glm::min(lo, c.lo);
    hi = glm::max(hi, c.hi);
  }
}

// Depth-first, siblings adjacent: a node's two children take the next two free slots, then the left
// subtree is laid out before the right one (the layout the hand-written builder had, and the traversal's).
// With the subtrees' counts every subtree's place is known beforehand: its children pair at firstNode, its
// descendants' pairs after it, its triangles from firstTriangle, the left subtree's before the right one's.
// So subtrees are laid out in parallel into arrays of their final size, the same bits as one recursion.
struct FlattenItem {
  const EmbreeBuildNode* node;
  uint32_t slot, depth, firstNode, firstTriangle;
};

struct FlattenStats {
  uint32_t leafCount = 0, largestLeaf = 0, maxDepth = 0;
};

struct BvhFlattener {
  Bvh& bvh;

  void leaf(const FlattenItem& item, FlattenStats& stats) {
    const EmbreeBuildNode& n = *item.node;
    bvh.nodes[item.slot].leftOrFirst = item.firstTriangle;
    bvh.nodes[item.slot].triCount = n.leafCount;
    std::copy(n.prims, n.prims + n.leafCount, bvh.triangleOrder.begin() + item.firstTriangle);
    stats.leafCount++;
    stats.largestLeaf = std::max(stats.largestLeaf, n.leafCount);
    stats.maxDepth = std::max(stats.maxDepth, item.depth);
  }

  // Writes interior node `item` and its children's boxes; returns the children to lay out.
  std::array<FlattenItem, 2> expand(const FlattenItem& item) {
    const EmbreeBuildNode& n = *item.node;
    if (!n.children[0] || !n.children[1])
      throw std::runtime_error("buildBvh: Embree left an interior node without two children");
    const EmbreeBuildNode* left = n.children[0];
    const EmbreeBuildNode* right = n.children[1];
    // The counts place every subtree: a wrong one would write into another's place, so each is checked.
    if (n.interiorBelow != 1 + interiorIn(left) + interiorIn(right) ||
        n.trianglesBelow != trianglesIn(left) + trianglesIn(right))
      throw std::runtime_error("buildBvh: Embree's tree does not match its subtree counts");
    bvh.nodes[item.slot].leftOrFirst = item.firstNode;
    bvh.nodes[item.slot].triCount = 0;
    for (uint32_t c = 0; c < 2; ++c) {
      const RTCBounds& b = n.childBounds[c];
      bvh.nodes[item.firstNode + c].boundsMin = {b.lower_x, b.lower_y, b.lower_z};
      bvh.nodes[item.firstNode + c].boundsMax = {b.upper_x, b.upper_y, b.upper_z};
    }
    const uint32_t depth = item.depth + 1, below = item.firstNode + 2;
    return {FlattenItem{left, item.firstNode, depth, below, item.firstTriangle},
            FlattenItem{right, item.firstNode + 1, depth, below + 2 * interiorIn(left),
                        item.firstTriangle + trianglesIn(left)}};
  }

  void node(const FlattenItem& item, FlattenStats& stats) {
    if (item.depth >= RL_BVH_STACK) throw std::runtime_error("buildBvh: Embree's tree is deeper than RL_BVH_STACK");
    if (item.node->leafCount > 0) return leaf(item, stats);
    const std::array<FlattenItem, 2> children = expand(item);
    node(children[0], stats);
    node(children[1], stats);
  }

  // The top of the tree, laid out here, down to subtrees small enough to share out (the largest split first,
  // until each holds at most 1/8 of a thread's share, or there are 64 a thread: Embree's tree is at most
  // RL_BVH_STACK deep, so a lopsided tree ends the splitting too).
  std::vector<FlattenItem> splitTop(const FlattenItem& root, uint32_t threads) {
    std::vector<FlattenItem> items{root};
    if (threads == 1) return items;
    const uint64_t total = interiorIn(root.node);
    while (items.size() < 64 * size_t(threads)) {
      auto largest = std::max_element(items.begin(), items.end(), [](const FlattenItem& a, const FlattenItem& b) {
        return interiorIn(a.node) < interiorIn(b.node);
      });
      if (interiorIn(largest->node) == 0 || uint64_t(interiorIn(largest->node)) * 8 * threads <= total) break;
      if (largest->depth >= RL_BVH_STACK)
        throw std::runtime_error("buildBvh: Embree's tree is deeper than RL_BVH_STACK");
      const std::array<FlattenItem, 2> children = expand(*largest);
      *largest = children[0];
      items.push_back(children[1]);
    }
    return items;
  }

  void flatten(const EmbreeBuildNode& root, uint32_t threads) {
    std::vector<FlattenItem> items = splitTop(FlattenItem{&root, 0, 0, 1, 0}, threads);
    // The big ones first: no thread left with one at the end.
    std::stable_sort(items.begin(), items.end(), [](const FlattenItem& a, const FlattenItem& b) {
      return interiorIn(a.node) > interiorIn(b.node);
    });
    std::vector<FlattenStats> stats(items.size());
    parallelFor(threads, items.size(), [&](size_t i) { node(items[i], stats[i]); });
    for (const FlattenStats& s : stats) {
      bvh.stats.leafCount += s.leafCount;
      bvh.stats.largestLeaf = std::max(bvh.stats.largestLeaf, s.largestLeaf);
      bvh.stats.maxDepth = std::max(bvh.stats.maxDepth, s.maxDepth);
    }
  }
};

// One rtcBuildBVH; null when Embree gave up (its depth limit with too small a leaf limit). `capacity` above
// `count` (room for the split references) with BvhSplits::Spatial.
const EmbreeBuildNode* runEmbreeBuild(RTCBVH handle, RTCBuildPrimitive* prims, size_t count, size_t capacity,
                                      uint32_t leafLimit, BvhSplits splits, const std::vector<Triangle>& triangles) {
  const bool spatial = splits == BvhSplits::Spatial;
  RTCBuildArguments args = rtcDefaultBuildArguments();
  args.byteSize = sizeof(args);
  args.buildQuality = spatial ? RTC_BUILD_QUALITY_HIGH : RTC_BUILD_QUALITY_MEDIUM;
  args.buildFlags = RTC_BUILD_FLAG_NONE;
  args.maxBranchingFactor = 2;
  args.maxDepth = kMaxBvhDepth;
  args.sahBlockSize = 1;
  args.minLeafSize = 1;
  args.maxLeafSize = leafLimit;
  // One interior-node visit (two child boxes) costs about one triangle test in our shaders' loop: the
  // weights the hand-written builder used; the spatial-split tree's in bvh.h.
  args.traversalCost = 1.0f;
  args.intersectionCost = spatial ? kSpatialSplitIntersectionCost : 1.0f;
  args.bvh = handle;
  args.primitives = prims;
  args.primitiveCount = count;
  args.primitiveArrayCapacity = spatial ? capacity : count;  // no room to split into: no spatial splits
  args.createNode = embreeCreateNode;
  args.setNodeChildren = embreeSetChildren;
  args.setNodeBounds = embreeSetBounds;
  args.createLeaf = embreeCreateLeaf;
  args.splitPrimitive = spatial ? splitTriangleReference : nullptr;
  args.buildProgress = nullptr;
  args.userPtr = const_cast<std::vector<Triangle>*>(&triangles);  // read only, by splitTriangleReference
  return static_cast<const EmbreeBuildNode*>(rtcBuildBVH(&args));
}

void emptyTree(Bvh& bvh) {
  // An empty scene still gets a root with inverted bounds (isEmptyTree), with two children so that the root is
  // an ordinary interior node. A min/max slab test enters an inverted box, so the CPU binary twin checks
  // isEmptyTree first, and the GPU's trees get boxes no ray enters (pairNodes; the wide collapse's empty root).
  gpu::BvhNode none{glm::vec3(1e30f), 0u, glm::vec3(-1e30f), 0u};
  bvh.nodes.assign(3, none);
  bvh.nodes[0].leftOrFirst = 1;
}

double msSince(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
}

// Lays out Embree's tree into arrays of their final size (each element written once: see BvhFlattener).
// Without splits the leaves hold every triangle once; with them, at least as many entries and at most the room
// they were given.
void flattenInto(Bvh& bvh, const EmbreeBuildNode& root, size_t triangleCount, size_t capacity, glm::vec3 lo,
                 glm::vec3 hi, uint32_t threads) {
  const size_t references = trianglesIn(&root);
  if (references < triangleCount || references > capacity)
    throw std::runtime_error("buildBvh: Embree's leaves hold " + std::to_string(references) + " triangles of " +
                             std::to_string(triangleCount));
  resizeFaultingInParallel(bvh.nodes, 1 + 2 * size_t(interiorIn(&root)), threads);
  bvh.nodes[0].boundsMin = lo;
  bvh.nodes[0].boundsMax = hi;
  resizeFaultingInParallel(bvh.triangleOrder, references, threads);
  BvhFlattener{bvh}.flatten(root, threads);
}

}  // namespace

Bvh buildBvh(const std::vector<Triangle>& triangles, uint32_t maxLeafSize, uint32_t threads, BvhSplits splits,
             double presplit) {
  const auto start = std::chrono::steady_clock::now();
  Bvh bvh;
  if (triangles.empty()) {
    emptyTree(bvh);
  } else {
    threads = workerThreads(threads, triangles.size(), 16384);
    const bool spatial = splits == BvhSplits::Spatial;
    const size_t cuts = spatial ? static_cast<size_t>(std::clamp(presplit, 0.0, 1.0) * triangles.size()) : 0;
    // Not zero-filled: every element is written before Embree reads it (10M triangles: 320 MB).
    const size_t capacity =
        triangles.size() + cuts + (spatial ? static_cast<size_t>(kSpatialSplitBudget * triangles.size()) : 0);
    auto prims = std::make_unique_for_overwrite<RTCBuildPrimitive[]>(capacity);
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    // The references Embree starts from: one a triangle, then the presplit pieces (none without cuts).
    auto fillReferences = [&] {
      fillPrimitives(triangles, threads, prims.get(), lo, hi);
      return presplitReferences(prims.get(), triangles.size(), cuts, triangles);
    };
    size_t count = fillReferences();
    bvh.stats.primitivesMs = msSince(start);
    const auto embreeStart = std::chrono::steady_clock::now();
    EmbreeDevice device;
    RTCBVH handle = rtcNewBVH(device.get());
    device.check("rtcNewBVH");
    uint32_t leafLimit = std::clamp(maxLeafSize, 1u, kEmbreeLeafLimit);
    const EmbreeBuildNode* root = nullptr;
    std::string error;
    // Embree throws away a build whose fallback splits reach maxDepth ("depth limit reached"); bigger
    // leaves need fewer levels, so that one error is retried with twice the leaf limit, from the primitives
    // refilled (Embree reorders the array it is given).
    for (bool retry = false;; retry = true) {
      if (retry) count = fillReferences();
      root = runEmbreeBuild(handle, prims.get(), count, capacity, leafLimit, splits, triangles);
      error = device.takeError();
      if (root || leafLimit >= kEmbreeLeafLimit || error.find("depth limit") == std::string::npos) break;
      leafLimit = std::min(leafLimit * 2, kEmbreeLeafLimit);
    }
    prims.reset();
    bvh.stats.embreeMs = msSince(embreeStart);
    const auto flattenStart = std::chrono::steady_clock::now();
    try {
      if (!root || !error.empty())
        throw std::runtime_error("buildBvh: Embree's rtcBuildBVH failed: " + (error.empty() ? "no tree" : error));
      flattenInto(bvh, *root, triangles.size(), capacity, lo, hi, threads);
    } catch (...) {
      rtcReleaseBVH(handle);
      throw;
    }
    rtcReleaseBVH(handle);
    bvh.stats.flattenMs = msSince(flattenStart);
    bvh.stats.maxLeafSize = leafLimit;
  }
  bvh.stats.nodeCount = static_cast<uint32_t>(bvh.nodes.size());
  bvh.stats.references = static_cast<uint32_t>(bvh.triangleOrder.size());
  bvh.stats.buildMs = msSince(start);
  bvh.stats.sahCost = bvhSahCost(bvh);
  return bvh;
}

}  // namespace raylab
