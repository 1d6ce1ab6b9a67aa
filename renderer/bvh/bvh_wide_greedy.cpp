// The greedy collapse's choices (renderer/bvh/bvh_wide_slots.h): a wide node's slots are the binary subtrees left
// after opening the largest-area interior one until 8 or only leaves remain, without pushing a leaf out of a
// node whose leaves fit; its binary leaves are leaf slots while the node's budget lasts (8 slots, 32 triangles).
#include <algorithm>

#include "renderer/bvh/bvh_wide.h"
#include "renderer/bvh/bvh_wide_slots.h"

namespace raylab {
namespace {

// Whether kids fit one wide node with every binary leaf among them as leaf slots.
bool fitsAsLeaves(const Bvh& binary, const std::vector<uint32_t>& kids) {
  uint32_t slots = 0, tris = 0;
  for (uint32_t k : kids) {
    const gpu::BvhNode& n = binary.nodes[k];
    slots += n.triCount > 0 ? wideLeafSlots(n.triCount) : 1u;
    tris += n.triCount;
  }
  return slots <= RL_BVH_WIDTH && tris <= kWideNodeTriangles;
}

// Up to 8 binary subtrees under binary node `index` (a binary leaf: itself).
std::vector<uint32_t> childrenOf(const Bvh& binary, uint32_t index) {
  const gpu::BvhNode& n = binary.nodes.at(index);
  if (n.triCount > 0) return {index};
  std::vector<uint32_t> kids{n.leftOrFirst, n.leftOrFirst + 1};
  std::vector<uint32_t> unopenable;
  while (kids.size() < RL_BVH_WIDTH) {
    int best = -1;
    float bestArea = -1.0f;
    for (int i = 0; i < int(kids.size()); ++i) {
      const gpu::BvhNode& k = binary.nodes[kids[i]];
      if (k.triCount == 0 && boxHalfArea(k) > bestArea &&
          std::find(unopenable.begin(), unopenable.end(), kids[i]) == unopenable.end()) {
        best = i;
        bestArea = boxHalfArea(k);
      }
    }
    if (best < 0) break;
    const gpu::BvhNode& open = binary.nodes[kids[best]];
    std::vector<uint32_t> next = kids;
    next.erase(next.begin() + best);
    next.push_back(open.leftOrFirst);
    next.push_back(open.leftOrFirst + 1);
    // Opening must not push a leaf out of the node when the current set fits.
    if (next.size() <= RL_BVH_WIDTH && (fitsAsLeaves(binary, next) || !fitsAsLeaves(binary, kids))) {
      kids = std::move(next);
    } else {
      unopenable.push_back(kids[best]);
    }
  }
  return kids;
}

}  // namespace

// Binary leaves as leaf slots while the budget lasts (in order), the rest as interior slots (a binary leaf
// that does not fit gets a wide node of its own).
std::vector<WideSlotChoice> WideSlotChooser::greedySlotsOf(uint32_t index) const {
  const std::vector<uint32_t> kids = childrenOf(binary_, index);
  uint32_t slots = uint32_t(kids.size()), tris = 0;
  std::vector<WideSlotChoice> out;
  for (uint32_t k : kids) {
    const gpu::BvhNode& n = binary_.nodes[k];
    const uint32_t extra = n.triCount > 0 ? wideLeafSlots(n.triCount) - 1u : 0u;
    const bool leaf = n.triCount > 0 && slots + extra <= RL_BVH_WIDTH && tris + n.triCount <= kWideNodeTriangles;
    if (leaf) slots += extra, tris += n.triCount;
    out.push_back({k, leaf});
  }
  return out;
}

}  // namespace raylab
