// WideSlotChooser (renderer/bvh/bvh_wide_slots.h): the triangle counts both collapses use, the SAH collapse's table
// and its choices, and the SAH cost of a built tree. Greedy's choices: bvh_wide_greedy.cpp.
#include <algorithm>
#include <limits>
#include <stdexcept>

#include "renderer/bvh/bvh_wide.h"
#include "renderer/bvh/bvh_wide_slots.h"
#include "renderer/parallel.h"

namespace raylab {
namespace {

constexpr uint8_t kLeaf = 0x10, kInterior = 0x20, kSplit = 0x30;  // kSplit | slots
constexpr float kNever = std::numeric_limits<float>::infinity();
// Subtrees rooted this deep are solved on the threads, the nodes above them after, on one.
constexpr uint32_t kParallelDepth = 8;

}  // namespace

WideSlotChooser::WideSlotChooser(const Bvh& binary, WideCollapse how, uint32_t threads) : binary_(binary), how_(how) {
  if (isEmptyTree(binary.nodes)) return;
  const size_t n = binary.nodes.size();
  threads = workerThreads(threads, n, 65536);
  // Zeros: triangles_ 0 is "not solved yet"; a node's costs and choices are written before anything reads them.
  resizeFaultingInParallel(triangles_, n, threads);
  if (how_ == WideCollapse::Sah) {
    resizeFaultingInParallel(cost_, n * 8, threads);
    resizeFaultingInParallel(choice_, n * 8, threads);
  }
  // The top of the tree in preorder; the nodes kParallelDepth down (or leaves above) are the subtrees' roots.
  std::vector<uint32_t> top, roots;
  std::vector<std::pair<uint32_t, uint32_t>> stack{{0u, 0u}};
  while (!stack.empty()) {
    const auto [index, depth] = stack.back();
    stack.pop_back();
    const gpu::BvhNode& node = binary.nodes.at(index);
    if (node.triCount > 0 || depth == kParallelDepth) {
      roots.push_back(index);
      continue;
    }
    top.push_back(index);
    stack.push_back({node.leftOrFirst + 1, depth + 1});
    stack.push_back({node.leftOrFirst, depth + 1});
  }
  parallelFor(threads, roots.size(), [&](size_t i) { solve(roots[i]); });
  for (auto it = top.rbegin(); it != top.rend(); ++it) solve(*it);  // children before parents
}

// Node `index`'s triangle count and, for the SAH, its costs and choices; its children's first where they are
// not solved yet (below the top).
void WideSlotChooser::solve(uint32_t index) {
  const gpu::BvhNode& node = binary_.nodes[index];
  const bool binaryLeaf = node.triCount > 0;
  const uint32_t left = node.leftOrFirst, right = node.leftOrFirst + 1;
  if (!binaryLeaf) {
    if (left <= index || right >= binary_.nodes.size())
      throw std::runtime_error("wide BVH: a binary node's children are not after it");
    if (triangles_[left] == 0) solve(left);
    if (triangles_[right] == 0) solve(right);
  }
  const uint32_t triangles = binaryLeaf ? node.triCount : triangles_[left] + triangles_[right];
  triangles_[index] = triangles;
  if (how_ != WideCollapse::Sah) return;
  const float area = boxHalfArea(node);
  const float leafCost = area * float(triangles) * kWideTriangleCost;
  // A leaf group takes one slot per 8 triangles when it is one binary leaf; a group of several leaves, one.
  const uint32_t leafSlots = binaryLeaf ? wideLeafSlots(triangles) : (triangles <= kWideLeafSlotTriangles ? 1u : 99u);
  // split[j]: the subtree as at most j slots shared between the two children.
  float split[RL_BVH_WIDTH + 1];
  std::fill(split, split + RL_BVH_WIDTH + 1, kNever);
  if (!binaryLeaf)
    for (uint32_t j = 2; j <= RL_BVH_WIDTH; ++j)
      for (uint32_t k = 1; k < j; ++k) split[j] = std::min(split[j], cost(left, k) + cost(right, j - k));
  // A wide node of its own: its box, and below it its own slots (a binary leaf: that leaf alone).
  const float interiorCost = area * kWideNodeCost + (binaryLeaf ? leafCost : split[RL_BVH_WIDTH]);
  float* c = &cost_[size_t(index) * 8];
  uint8_t* ch = &choice_[size_t(index) * 8];
  for (uint32_t i = 1; i <= RL_BVH_WIDTH; ++i) {
    // Equal costs: a leaf before a node, fewer slots before more.
    float best = kNever;
    uint8_t choice = 0;
    if (leafSlots <= i) best = leafCost, choice = kLeaf;
    if (interiorCost < best) best = interiorCost, choice = kInterior;
    if (i >= 2 && split[i] < best) best = split[i], choice = uint8_t(kSplit | i);
    if (i >= 2 && c[i - 2] <= best) best = c[i - 2], choice = ch[i - 2];
    c[i - 1] = best;
    ch[i - 1] = choice;
  }
}

// The slots that node `index`'s choice for at most `slots` slots stands for.
void WideSlotChooser::expand(uint32_t index, uint32_t slots, std::vector<WideSlotChoice>& out) const {
  const uint8_t choice = choice_[size_t(index) * 8 + slots - 1];
  if (choice == kLeaf) {
    out.push_back({index, true});
  } else if (choice == kInterior) {
    out.push_back({index, false});
  } else {
    expandSplit(index, choice & 0x0Fu, out);
  }
}

// The cheapest share of `slots` between node `index`'s children (the first of equals, as solve found it).
void WideSlotChooser::expandSplit(uint32_t index, uint32_t slots, std::vector<WideSlotChoice>& out) const {
  const uint32_t left = binary_.nodes[index].leftOrFirst, right = left + 1;
  uint32_t bestK = 1;
  float best = kNever;
  for (uint32_t k = 1; k < slots; ++k) {
    const float c = cost(left, k) + cost(right, slots - k);
    if (c < best) best = c, bestK = k;
  }
  expand(left, bestK, out);
  expand(right, slots - bestK, out);
}

std::vector<WideSlotChoice> WideSlotChooser::slotsOf(uint32_t index) const {
  if (triangles_.empty()) return {};
  return how_ == WideCollapse::Sah ? sahSlotsOf(index) : greedySlotsOf(index);
}

std::vector<WideSlotChoice> WideSlotChooser::sahSlotsOf(uint32_t index) const {
  std::vector<WideSlotChoice> out;
  if (binary_.nodes[index].triCount > 0) {
    out.push_back({index, true});  // a binary leaf as a wide node: that leaf alone
    return out;
  }
  expandSplit(index, RL_BVH_WIDTH, out);
  // The node's leaf block holds 32 triangles: the largest groups beyond it become wide nodes of their own.
  for (;;) {
    uint32_t total = 0, largest = 0;
    size_t largestAt = 0;
    for (size_t i = 0; i < out.size(); ++i) {
      if (!out[i].leaf) continue;
      const uint32_t t = triangles_[out[i].binary];
      total += t;
      if (t > largest) largest = t, largestAt = i;
    }
    if (total <= kWideNodeTriangles) break;
    out[largestAt].leaf = false;
  }
  return out;
}

double wideSahCost(const BvhWide& wide, const Bvh& binary) {
  if (wide.nodes.empty() || isEmptyTree(binary.nodes)) return 0.0;
  const gpu::BvhNode& rootBox = binary.nodes[0];
  const double rootArea = boxHalfArea(rootBox);
  double sum = 0.0;
  std::vector<std::pair<uint32_t, float>> stack{{0u, boxHalfArea(rootBox)}};  // node, its box's half area
  while (!stack.empty()) {
    const auto [index, area] = stack.back();
    stack.pop_back();
    sum += double(area) * kWideNodeCost;
    const gpu::BvhWideNode& node = wide.nodes.at(index);
    for (uint32_t s = 0; s < RL_BVH_WIDTH; ++s) {
      const WideSlot kind = slotKind(node, s);
      if (kind == WideSlot::Empty) continue;
      const WideChildBox box = decodeChildBox(node, s);
      const float childArea = boxHalfArea(box.min, box.max);
      if (kind == WideSlot::Interior) {
        stack.push_back({slotChildIndex(node, s), childArea});
      } else {
        sum += double(childArea) * wideLeafRange(node, s).count * kWideTriangleCost;
      }
    }
  }
  return rootArea > 0.0 ? sum / rootArea : sum;
}

}  // namespace raylab
