#include "renderer/bvh_wide.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "renderer/bvh_wide_plan.h"

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

uint32_t slotsOfLeaf(uint32_t count) { return (count + kWideLeafSlotTriangles - 1) / kWideLeafSlotTriangles; }

void setMeta(gpu::BvhWideNode& node, uint32_t slot, uint32_t meta) {
  uint32_t& w = node.meta[slot >> 2];
  const uint32_t shift = (slot & 3u) * 8u;
  w = (w & ~(0xFFu << shift)) | (meta << shift);
}

// One slot's content while a node is built: a binary interior node (or a binary leaf given a wide node of its
// own, when the node's leaf budget is spent), or up to 8 triangles of a binary leaf.
struct SlotEntry {
  uint32_t binary;  // binary node index
  bool leaf;
  uint32_t first, count;  // leaf: the triangles, at their old BVH positions
};

struct WidePlanner {
  const Bvh& binary;

  // Whether kids fit one wide node with every binary leaf among them as leaf slots: 8 slots, a leaf taking one
  // per 8 triangles, and at most 32 triangles.
  bool fitsAsLeaves(const std::vector<uint32_t>& kids) const {
    uint32_t slots = 0, tris = 0;
    for (uint32_t k : kids) {
      const gpu::BvhNode& n = binary.nodes[k];
      slots += n.triCount > 0 ? slotsOfLeaf(n.triCount) : 1u;
      tris += n.triCount;
    }
    return slots <= RL_BVH_WIDTH && tris <= kWideNodeTriangles;
  }

  // Up to 8 binary subtrees under binary node `index`: open the largest-area interior one (that keeps the
  // node within its leaf budget) until 8 or none remain. Empty boxes (the empty scene's placeholders) are dropped.
  std::vector<uint32_t> childrenOf(uint32_t index) const {
    const gpu::BvhNode& n = binary.nodes.at(index);
    std::vector<uint32_t> kids;
    if (n.triCount > 0) {
      kids.push_back(index);  // a leaf root: one leaf child
      return kids;
    }
    for (uint32_t c : {n.leftOrFirst, n.leftOrFirst + 1})
      if (!emptyBox(binary.nodes.at(c))) kids.push_back(c);
    std::vector<uint32_t> unopenable;
    while (kids.size() < RL_BVH_WIDTH) {
      int best = -1;
      float bestArea = -1.0f;
      for (int i = 0; i < int(kids.size()); ++i) {
        const gpu::BvhNode& k = binary.nodes[kids[i]];
        if (k.triCount == 0 && halfArea(k) > bestArea &&
            std::find(unopenable.begin(), unopenable.end(), kids[i]) == unopenable.end()) {
          best = i;
          bestArea = halfArea(k);
        }
      }
      if (best < 0) break;
      const gpu::BvhNode& open = binary.nodes[kids[best]];
      std::vector<uint32_t> next = kids;
      next.erase(next.begin() + best);
      for (uint32_t c : {open.leftOrFirst, open.leftOrFirst + 1})
        if (!emptyBox(binary.nodes.at(c))) next.push_back(c);
      // Opening must not push a leaf out of the node when the current set fits.
      if (next.size() <= RL_BVH_WIDTH && (fitsAsLeaves(next) || !fitsAsLeaves(kids))) {
        kids = std::move(next);
      } else {
        unopenable.push_back(kids[best]);
      }
    }
    return kids;
  }

  // The slots' contents: binary leaves as leaf slots while the budget lasts (in order), the rest as interior
  // children (a binary leaf that does not fit gets a wide node of its own).
  std::vector<SlotEntry> entriesOf(const std::vector<uint32_t>& kids) const {
    uint32_t slots = uint32_t(kids.size()), tris = 0;
    std::vector<SlotEntry> entries;
    for (uint32_t k : kids) {
      const gpu::BvhNode& n = binary.nodes[k];
      const uint32_t extra = n.triCount > 0 ? slotsOfLeaf(n.triCount) - 1u : 0u;
      if (n.triCount > 0 && slots + extra <= RL_BVH_WIDTH && tris + n.triCount <= kWideNodeTriangles) {
        slots += extra;
        tris += n.triCount;
        for (uint32_t f = 0; f < n.triCount; f += kWideLeafSlotTriangles)
          entries.push_back({k, true, n.leftOrFirst + f, std::min(kWideLeafSlotTriangles, n.triCount - f)});
      } else {
        entries.push_back({k, false, 0, 0});
      }
    }
    return entries;
  }

  WideNodePlan plan(uint32_t binaryIndex) const {
    WideNodePlan p;
    // A binary leaf reached as a wide node of its own (its parent's budget was spent) is that node's one leaf.
    const std::vector<SlotEntry> entries = entriesOf(childrenOf(binaryIndex));
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
      uint32_t leafOffset = 0;
      for (const auto& [b, o] : offsetOf)
        if (b == e.binary) leafOffset = o;
      leafOffset += e.first - binary.nodes[e.binary].leftOrFirst;
      setMeta(p.node, s, ((e.count - 1u) << 5) | leafOffset);
      p.leafSlots++;
    }
    return p;
  }

  // The leaf block: binary leaves by decreasing size (a leaf's slots stay together, in order), so the block
  // starts with a leaf of 2 or more triangles and no meta byte is 0; all single triangles: from offset 1.
  // Returns each leaf's offset in the block.
  std::vector<std::pair<uint32_t, uint32_t>> planLeafBlock(const std::vector<SlotEntry>& entries,
                                                           WideNodePlan& p) const {
    uint32_t largest = 0;
    for (const SlotEntry& e : entries)
      if (e.leaf && (p.leaves.empty() || p.leaves.back() != e.binary)) {
        p.leaves.push_back(e.binary);
        largest = std::max(largest, binary.nodes[e.binary].triCount);
      }
    std::stable_sort(p.leaves.begin(), p.leaves.end(), [&](uint32_t a, uint32_t b) {
      return binary.nodes[a].triCount > binary.nodes[b].triCount;
    });
    p.blockStart = largest == 1 ? 1u : 0u;
    std::vector<std::pair<uint32_t, uint32_t>> offsetOf;  // (binary leaf, its offset in the block)
    uint32_t offset = p.blockStart;
    for (uint32_t b : p.leaves) {
      offsetOf.push_back({b, offset});
      offset += binary.nodes[b].triCount;
    }
    return offsetOf;
  }
};

}  // namespace

WideNodePlan planWideNode(const Bvh& binary, uint32_t binaryIndex) { return WidePlanner{binary}.plan(binaryIndex); }

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
