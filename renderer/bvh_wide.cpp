#include "renderer/bvh_wide.h"

#include <algorithm>
#include <array>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace raylab {
namespace {

bool emptyBox(const gpu::BvhNode& n) { return n.boundsMin.x > n.boundsMax.x; }

float halfArea(const gpu::BvhNode& n) {
  glm::vec3 d = n.boundsMax - n.boundsMin;
  return d.x * d.y + d.y * d.z + d.z * d.x;
}

float scaleOf(uint32_t biasedExponent) { return std::bit_cast<float>(biasedExponent << 23); }

// The decode the shaders do, in float: origin + q * 2^e (the product is exact, so a fused multiply-add on the
// GPU gives the same value).
float decodePlane(float origin, uint32_t q, float scale) { return origin + float(q) * scale; }

void setByte(uint32_t* words, uint32_t axis, uint32_t slot, uint32_t value) {
  uint32_t& w = words[2 * axis + (slot >> 2)];
  const uint32_t shift = (slot & 3u) * 8u;
  w = (w & ~(0xFFu << shift)) | (value << shift);
}

uint32_t getByte(const uint32_t* words, uint32_t axis, uint32_t slot) {
  return (words[2 * axis + (slot >> 2)] >> ((slot & 3u) * 8u)) & 0xFFu;
}

// Quantizes one axis of all children against origin `lo`: the smallest power-of-two scale whose 255 steps span
// the node and for which every rounded-outwards child plane, decoded in float, still contains the exact one.
void quantizeAxis(gpu::BvhWideNode& node, uint32_t axis, const std::vector<std::pair<uint32_t, gpu::BvhNode>>& kids,
                  float lo, float hi) {
  const double extent = double(hi) - double(lo);
  int e = extent > 0.0 ? int(std::ceil(std::log2(extent / 255.0))) : -126;
  e = std::clamp(e, -126, 127);
  for (;; ++e) {
    if (e > 127) throw std::runtime_error("wide BVH: a node's extent does not fit an 8-bit quantization");
    const uint32_t biased = uint32_t(e + 127);
    const float scale = scaleOf(biased);
    bool fits = true;
    for (const auto& [slot, child] : kids) {
      const float cmin = child.boundsMin[axis], cmax = child.boundsMax[axis];
      double ql = std::floor((double(cmin) - double(lo)) / double(scale));
      double qh = std::ceil((double(cmax) - double(lo)) / double(scale));
      uint32_t qlo = uint32_t(std::clamp(ql, 0.0, 255.0));
      int64_t qhi = int64_t(std::clamp(qh, 0.0, 256.0));
      // Float rounding of the decode may move a plane inwards: step outwards until it contains the child.
      while (qlo > 0 && decodePlane(lo, qlo, scale) > cmin) --qlo;
      while (qhi <= 255 && decodePlane(lo, uint32_t(qhi), scale) < cmax) ++qhi;
      if (qhi > 255) {
        fits = false;
        break;
      }
      setByte(node.qlo, axis, slot, qlo);
      setByte(node.qhi, axis, slot, uint32_t(qhi));
    }
    if (!fits) continue;
    node.exponents |= biased << (8u * axis);
    return;
  }
}

// Greedy slot assignment by direction (CWBVH): slot s stands for the corner whose axis k is positive where
// bit k of s is set; the child whose centroid lies furthest towards a corner takes it, best pairs first.
std::array<int, RL_BVH_WIDTH> assignSlots(const std::vector<gpu::BvhNode>& kids, glm::vec3 centre) {
  struct Pair {
    float cost;
    int child, slot;
  };
  std::vector<Pair> pairs;
  for (int c = 0; c < int(kids.size()); ++c) {
    const glm::vec3 d = 0.5f * (kids[c].boundsMin + kids[c].boundsMax) - centre;
    for (int s = 0; s < int(RL_BVH_WIDTH); ++s) {
      const glm::vec3 corner((s & 1) ? 1.0f : -1.0f, (s & 2) ? 1.0f : -1.0f, (s & 4) ? 1.0f : -1.0f);
      pairs.push_back({-glm::dot(d, corner), c, s});
    }
  }
  std::stable_sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) { return a.cost < b.cost; });
  std::array<int, RL_BVH_WIDTH> childOfSlot;
  childOfSlot.fill(-1);
  std::vector<bool> placed(kids.size(), false);
  for (const Pair& p : pairs) {
    if (placed[p.child] || childOfSlot[p.slot] >= 0) continue;
    placed[p.child] = true;
    childOfSlot[p.slot] = p.child;
  }
  return childOfSlot;
}

struct Collapser {
  const Bvh& binary;
  BvhWide& out;

  // Up to 8 binary subtrees under binary node `index`: open the largest-area interior one until 8 or only
  // leaves remain. Empty boxes (the empty scene's placeholder nodes) are dropped.
  std::vector<uint32_t> childrenOf(uint32_t index) const {
    const gpu::BvhNode& n = binary.nodes.at(index);
    std::vector<uint32_t> kids;
    if (n.triCount > 0) {
      kids.push_back(index);  // a leaf root: one leaf child
      return kids;
    }
    for (uint32_t c : {n.leftOrFirst, n.leftOrFirst + 1})
      if (!emptyBox(binary.nodes.at(c))) kids.push_back(c);
    while (kids.size() < RL_BVH_WIDTH) {
      int best = -1;
      float bestArea = -1.0f;
      for (int i = 0; i < int(kids.size()); ++i) {
        const gpu::BvhNode& k = binary.nodes[kids[i]];
        if (k.triCount == 0 && halfArea(k) > bestArea) {
          best = i;
          bestArea = halfArea(k);
        }
      }
      if (best < 0) break;
      const gpu::BvhNode& open = binary.nodes[kids[best]];
      kids.erase(kids.begin() + best);
      for (uint32_t c : {open.leftOrFirst, open.leftOrFirst + 1})
        if (!emptyBox(binary.nodes.at(c))) kids.push_back(c);
    }
    return kids;
  }

  void build(uint32_t wideIndex, uint32_t binaryIndex, uint32_t depth) {
    if (depth >= RL_BVH_STACK) throw std::runtime_error("wide BVH: deeper than the traversal stack");
    out.stats.maxDepth = std::max(out.stats.maxDepth, depth);
    const std::vector<uint32_t> kidIndices = childrenOf(binaryIndex);
    std::vector<gpu::BvhNode> kids;
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (uint32_t k : kidIndices) {
      kids.push_back(binary.nodes[k]);
      lo = glm::min(lo, kids.back().boundsMin);
      hi = glm::max(hi, kids.back().boundsMax);
    }
    gpu::BvhWideNode node{};
    if (kids.empty()) {  // the empty scene: a root without children
      out.nodes[wideIndex] = node;
      return;
    }
    const std::array<int, RL_BVH_WIDTH> childOfSlot = assignSlots(kids, 0.5f * (lo + hi));
    std::vector<std::pair<uint32_t, gpu::BvhNode>> placed;
    uint32_t interiorMask = 0, leafMask = 0;
    for (uint32_t s = 0; s < RL_BVH_WIDTH; ++s) {
      if (childOfSlot[s] < 0) continue;
      const gpu::BvhNode& k = kids[childOfSlot[s]];
      placed.push_back({s, k});
      (k.triCount > 0 ? leafMask : interiorMask) |= 1u << s;
    }
    node.origin = lo;
    for (uint32_t axis = 0; axis < 3; ++axis) quantizeAxis(node, axis, placed, lo[axis], hi[axis]);
    node.masks = interiorMask | (leafMask << 8);
    node.childBase = uint32_t(out.nodes.size());
    node.leafBase = uint32_t(out.leaves.size());
    out.nodes.resize(out.nodes.size() + std::popcount(interiorMask));
    std::vector<std::pair<uint32_t, uint32_t>> interiors;  // (wide index, binary index), in slot order
    for (uint32_t s = 0; s < RL_BVH_WIDTH; ++s) {
      if (childOfSlot[s] < 0) continue;
      const uint32_t b = kidIndices[childOfSlot[s]];
      const gpu::BvhNode& k = binary.nodes[b];
      if (k.triCount > 0)
        out.leaves.push_back({k.leftOrFirst, k.triCount});
      else
        interiors.push_back({node.childBase + uint32_t(interiors.size()), b});
    }
    out.nodes[wideIndex] = node;
    for (const auto& [w, b] : interiors) build(w, b, depth + 1);
  }
};

}  // namespace

BvhWide collapseBvh(const Bvh& binary) {
  const auto start = std::chrono::steady_clock::now();
  BvhWide wide;
  wide.nodes.resize(1);
  if (!binary.nodes.empty()) Collapser{binary, wide}.build(0, 0, 0);
  wide.stats.nodeCount = uint32_t(wide.nodes.size());
  wide.stats.leafCount = uint32_t(wide.leaves.size());
  wide.stats.buildMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return wide;
}

WideChildBox decodeChildBox(const gpu::BvhWideNode& node, uint32_t slot) {
  WideChildBox b;
  for (uint32_t axis = 0; axis < 3; ++axis) {
    const float scale = scaleOf((node.exponents >> (8u * axis)) & 0xFFu);
    b.min[axis] = decodePlane(node.origin[axis], getByte(node.qlo, axis, slot), scale);
    b.max[axis] = decodePlane(node.origin[axis], getByte(node.qhi, axis, slot), scale);
  }
  return b;
}

glm::vec3 wideScale(const gpu::BvhWideNode& node) {
  glm::vec3 s;
  for (uint32_t axis = 0; axis < 3; ++axis) s[axis] = scaleOf((node.exponents >> (8u * axis)) & 0xFFu);
  return s;
}

glm::vec3 wideLowPlanes(const gpu::BvhWideNode& node, uint32_t slot) {
  return {float(getByte(node.qlo, 0, slot)), float(getByte(node.qlo, 1, slot)), float(getByte(node.qlo, 2, slot))};
}

glm::vec3 wideHighPlanes(const gpu::BvhWideNode& node, uint32_t slot) {
  return {float(getByte(node.qhi, 0, slot)), float(getByte(node.qhi, 1, slot)), float(getByte(node.qhi, 2, slot))};
}

WideSlot slotKind(const gpu::BvhWideNode& node, uint32_t slot) {
  if ((node.masks >> slot) & 1u) return WideSlot::Interior;
  if ((node.masks >> (8u + slot)) & 1u) return WideSlot::Leaf;
  return WideSlot::Empty;
}

uint32_t slotChildIndex(const gpu::BvhWideNode& node, uint32_t slot) {
  const uint32_t below = (1u << slot) - 1u;
  if (slotKind(node, slot) == WideSlot::Interior) return node.childBase + std::popcount(node.masks & 0xFFu & below);
  return node.leafBase + std::popcount((node.masks >> 8) & 0xFFu & below);
}

}  // namespace raylab
