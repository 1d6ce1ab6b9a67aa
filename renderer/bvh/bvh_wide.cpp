#include "renderer/bvh/bvh_wide.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "renderer/bvh/bvh_wide_plan.h"

namespace raylab {
namespace {

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

void setMeta(gpu::BvhWideNode& node, uint32_t slot, uint32_t meta) {
  uint32_t& w = node.meta[slot >> 2];
  const uint32_t shift = (slot & 3u) * 8u;
  w = (w & ~(0xFFu << shift)) | (meta << shift);
}

// One slot's content while a node is built: a binary node as an interior slot, or up to 8 triangles of a leaf
// group (the triangles under a binary node: a binary leaf of more than 8 takes several slots).
struct SlotEntry {
  uint32_t binary;  // binary node index: the interior child or the leaf group's root
  bool leaf;
  uint32_t first, count;  // leaf: the slot's triangles, counted from the group's first
};

struct WidePlanner {
  const Bvh& binary;
  const WideSlotChooser& slots;

  std::vector<SlotEntry> entriesOf(uint32_t binaryIndex) const {
    std::vector<SlotEntry> entries;
    for (const WideSlotChoice& c : slots.slotsOf(binaryIndex)) {
      if (!c.leaf) {
        entries.push_back({c.binary, false, 0, 0});
        continue;
      }
      const uint32_t triangles = slots.trianglesUnder(c.binary);
      for (uint32_t f = 0; f < triangles; f += kWideLeafSlotTriangles)
        entries.push_back({c.binary, true, f, std::min(kWideLeafSlotTriangles, triangles - f)});
    }
    return entries;
  }

  // The binary leaves under binary node `index`, left to right: a leaf group's triangles in block order.
  void leavesUnder(uint32_t index, std::vector<uint32_t>& out) const {
    const gpu::BvhNode& n = binary.nodes[index];
    if (n.triCount > 0) {
      out.push_back(index);
      return;
    }
    leavesUnder(n.leftOrFirst, out);
    leavesUnder(n.leftOrFirst + 1, out);
  }

  WideNodePlan plan(uint32_t binaryIndex) const {
    WideNodePlan p;
    const std::vector<SlotEntry> entries = entriesOf(binaryIndex);
    std::vector<gpu::BvhNode> kids;
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const SlotEntry& e : entries) {
      kids.push_back(binary.nodes[e.binary]);
      lo = glm::min(lo, kids.back().boundsMin);
      hi = glm::max(hi, kids.back().boundsMax);
    }
    if (kids.empty()) {  // the empty scene: a root without children
      p.empty = true;
      return p;
    }
    if (kids.size() > RL_BVH_WIDTH) throw std::runtime_error("wide BVH: a node planned with more than 8 slots");
    const std::array<int, RL_BVH_WIDTH> childOfSlot = assignSlots(kids, 0.5f * (lo + hi));
    std::vector<std::pair<uint32_t, gpu::BvhNode>> placed;
    uint32_t interiorMask = 0;
    for (uint32_t s = 0; s < RL_BVH_WIDTH; ++s) {
      if (childOfSlot[s] < 0) continue;
      placed.push_back({s, kids[childOfSlot[s]]});
      if (!entries[childOfSlot[s]].leaf) interiorMask |= 1u << s;
    }
    p.node.origin = lo;
    for (uint32_t axis = 0; axis < 3; ++axis) quantizeAxis(p.node, axis, placed, lo[axis], hi[axis]);
    p.node.exponents |= interiorMask << 24;
    const std::vector<std::pair<uint32_t, uint32_t>> offsetOf = planLeafBlock(entries, p);
    for (uint32_t s = 0; s < RL_BVH_WIDTH; ++s) {
      if (childOfSlot[s] < 0) continue;
      const SlotEntry& e = entries[childOfSlot[s]];
      if (!e.leaf) {
        p.interiors.push_back(e.binary);
        continue;
      }
      uint32_t groupOffset = 0;
      for (const auto& [b, o] : offsetOf)
        if (b == e.binary) groupOffset = o;
      setMeta(p.node, s, ((e.count - 1u) << 5) | (groupOffset + e.first));
      p.leafSlots++;
    }
    return p;
  }

  // The leaf block: leaf groups by decreasing size (a group's slots stay together, in order), so the block
  // starts with a group of 2 or more triangles and no meta byte is 0; all single triangles: from offset 1.
  // Fills p.leaves (the groups' binary leaves in block order) and returns each group's offset in the block.
  std::vector<std::pair<uint32_t, uint32_t>> planLeafBlock(const std::vector<SlotEntry>& entries,
                                                           WideNodePlan& p) const {
    std::vector<uint32_t> groups;
    for (const SlotEntry& e : entries)
      if (e.leaf && (groups.empty() || groups.back() != e.binary)) groups.push_back(e.binary);
    std::stable_sort(groups.begin(), groups.end(), [&](uint32_t a, uint32_t b) {
      return slots.trianglesUnder(a) > slots.trianglesUnder(b);
    });
    p.blockStart = !groups.empty() && slots.trianglesUnder(groups.front()) == 1 ? 1u : 0u;
    std::vector<std::pair<uint32_t, uint32_t>> offsetOf;  // (group, its offset in the block)
    uint32_t offset = p.blockStart;
    for (uint32_t g : groups) {
      offsetOf.push_back({g, offset});
      offset += slots.trianglesUnder(g);
      leavesUnder(g, p.leaves);
    }
    return offsetOf;
  }
};

}  // namespace

WideNodePlan planWideNode(const Bvh& binary, const WideSlotChooser& slots, uint32_t binaryIndex) {
  return WidePlanner{binary, slots}.plan(binaryIndex);
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
  if ((wideInteriorMask(node) >> slot) & 1u) return WideSlot::Interior;
  if (wideMeta(node, slot) != 0) return WideSlot::Leaf;
  return WideSlot::Empty;
}

uint32_t slotChildIndex(const gpu::BvhWideNode& node, uint32_t slot) {
  return node.childBase + std::popcount(wideInteriorMask(node) & ((1u << slot) - 1u));
}

WideLeafRange wideLeafRange(const gpu::BvhWideNode& node, uint32_t slot) {
  const uint32_t meta = wideMeta(node, slot);
  return {node.triBase + (meta & 31u), (meta >> 5) + 1u};
}

}  // namespace raylab
