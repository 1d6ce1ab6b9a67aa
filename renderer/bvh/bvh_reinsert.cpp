#include "renderer/bvh/bvh_reinsert.h"

#include <algorithm>
#include <chrono>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

#include "renderer/bvh/bvh_sah.h"

namespace raylab {
namespace {

constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();

// A node that knows its parent, so a subtree can be taken out and put back elsewhere.
struct Node {
  glm::vec3 lo, hi;
  uint32_t parent = kNone;
  uint32_t child[2] = {kNone, kNone};
  uint32_t first = 0, count = 0;  // a leaf's entries in triangleOrder (count > 0)
  bool leaf() const { return count > 0; }
};

float area(glm::vec3 lo, glm::vec3 hi) {
  const glm::vec3 d = glm::max(hi - lo, glm::vec3(0.0f));
  return 2.0f * (d.x * d.y + d.y * d.z + d.z * d.x);
}
float area(const Node& n) { return area(n.lo, n.hi); }
float unionArea(const Node& a, const Node& b) { return area(glm::min(a.lo, b.lo), glm::max(a.hi, b.hi)); }

struct Tree {
  std::vector<Node> nodes;
  uint32_t root = 0;
  // The nodes one reinsertion changed, as they were, so that a move that adds area is taken back.
  std::vector<std::pair<uint32_t, Node>> journal;
  std::vector<uint32_t> stamp;  // journal generation that saved each node
  uint32_t generation = 0, rootBefore = 0;

  Node& edit(uint32_t i) {
    if (stamp[i] != generation) stamp[i] = generation, journal.push_back({i, nodes[i]});
    return nodes[i];
  }
  void begin() {
    ++generation;
    journal.clear();
    rootBefore = root;
  }
  // The change of the interior nodes' total area since begin(): only journaled nodes changed.
  double areaChange() const {
    double change = 0.0;
    for (const auto& [i, old] : journal) change += (nodes[i].leaf() ? 0.0 : area(nodes[i])) - (old.leaf() ? 0.0 : area(old));
    return change;
  }
  void undo() {
    for (auto it = journal.rbegin(); it != journal.rend(); ++it) nodes[it->first] = it->second;
    root = rootBefore;
  }

  void refitUp(uint32_t i) {
    for (; i != kNone; i = nodes[i].parent) {
      const Node &a = nodes[nodes[i].child[0]], &b = nodes[nodes[i].child[1]];
      const glm::vec3 lo = glm::min(a.lo, b.lo), hi = glm::max(a.hi, b.hi);
      Node& n = edit(i);
      n.lo = lo;
      n.hi = hi;
    }
  }
  void replaceChild(uint32_t parent, uint32_t from, uint32_t to) {
    if (parent == kNone) {
      root = to;
    } else {
      Node& p = edit(parent);
      p.child[p.child[0] == from ? 0 : 1] = to;
    }
    edit(to).parent = parent;
  }
  double interiorArea() const {
    double sum = 0.0;
    for (const Node& n : nodes)
      if (!n.leaf()) sum += area(n);
    return sum;
  }
  uint32_t depth() const {
    uint32_t deepest = 0;
    std::vector<std::pair<uint32_t, uint32_t>> stack{{root, 0}};
    while (!stack.empty()) {
      const auto [i, d] = stack.back();
      stack.pop_back();
      deepest = std::max(deepest, d);
      if (!nodes[i].leaf()) stack.push_back({nodes[i].child[0], d + 1}), stack.push_back({nodes[i].child[1], d + 1});
    }
    return deepest;
  }

  // The node whose new sibling `s` adds the least area: the new parent's area plus every ancestor's growth.
  // Branch and bound from the root, cheapest induced cost first; a subtree is skipped once even `s`'s own area
  // on top of what its ancestors would grow cannot beat the best found.
  uint32_t bestSibling(uint32_t s) const {
    const Node& sub = nodes[s];
    const float own = area(sub);
    using Item = std::pair<float, uint32_t>;  // induced cost (the ancestors' growth), node
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
    queue.push({0.0f, root});
    uint32_t best = root;
    float bestCost = std::numeric_limits<float>::infinity();
    while (!queue.empty()) {
      const auto [induced, x] = queue.top();
      queue.pop();
      if (induced + own >= bestCost) break;
      const float direct = unionArea(nodes[x], sub);
      if (induced + direct < bestCost) bestCost = induced + direct, best = x;
      if (nodes[x].leaf()) continue;
      const float below = induced + direct - area(nodes[x]);
      if (below + own < bestCost) queue.push({below, nodes[x].child[0]}), queue.push({below, nodes[x].child[1]});
    }
    return best;
  }

  // Makes the free node `f` the parent of `x` and `s`, where `x` was.
  void insertAsSibling(uint32_t s, uint32_t x, uint32_t f) {
    const uint32_t up = nodes[x].parent;
    Node& n = edit(f);
    n.child[0] = x;
    n.child[1] = s;
    n.count = 0;
    replaceChild(up, x, f);
    edit(x).parent = f;
    edit(s).parent = f;
    refitUp(f);
  }

  // Bittner et al.'s step: take `n` and its parent out (the sibling takes the parent's place), then put n's two
  // children back where each costs least, with n and its parent as their new parents. Kept only if the tree's
  // interior area fell; false (and the tree as it was) otherwise.
  bool reinsert(uint32_t n) {
    const uint32_t p = nodes[n].parent;
    if (nodes[n].leaf() || p == kNone || nodes[p].parent == kNone) return false;
    begin();
    const uint32_t g = nodes[p].parent;
    const uint32_t sibling = nodes[p].child[nodes[p].child[0] == n ? 1 : 0];
    replaceChild(g, p, sibling);  // n and p are journaled where they become new parents, before any change
    refitUp(g);
    const uint32_t a = nodes[n].child[0], b = nodes[n].child[1];
    edit(a).parent = kNone;
    edit(b).parent = kNone;
    insertAsSibling(a, bestSibling(a), n);
    insertAsSibling(b, bestSibling(b), p);
    if (areaChange() < 0.0) return true;
    undo();
    return false;
  }
};

Tree treeOf(const Bvh& bvh) {
  Tree t;
  t.nodes.resize(bvh.nodes.size());
  for (uint32_t i = 0; i < bvh.nodes.size(); ++i) {
    const gpu::BvhNode& b = bvh.nodes[i];
    Node& n = t.nodes[i];
    n.lo = b.boundsMin;
    n.hi = b.boundsMax;
    if (b.triCount > 0) {
      n.first = b.leftOrFirst;
      n.count = b.triCount;
    } else {
      n.child[0] = b.leftOrFirst;
      n.child[1] = b.leftOrFirst + 1;
      t.nodes[b.leftOrFirst].parent = t.nodes[b.leftOrFirst + 1].parent = i;
    }
  }
  return t;
}

// Depth first from the root, siblings adjacent, leaf entries in the order the leaves come.
void layOut(const Tree& t, Bvh& bvh) {
  std::vector<gpu::BvhNode> nodes;
  std::vector<uint32_t> order;
  nodes.reserve(t.nodes.size());
  order.reserve(bvh.triangleOrder.size());
  nodes.push_back({});
  std::vector<std::pair<uint32_t, uint32_t>> stack{{t.root, 0}};  // tree node, output slot
  uint32_t leaves = 0;
  while (!stack.empty()) {
    const auto [i, slot] = stack.back();
    stack.pop_back();
    const Node& n = t.nodes[i];
    gpu::BvhNode out{n.lo, 0u, n.hi, n.count};
    if (n.leaf()) {
      out.leftOrFirst = static_cast<uint32_t>(order.size());
      order.insert(order.end(), bvh.triangleOrder.begin() + n.first, bvh.triangleOrder.begin() + n.first + n.count);
      ++leaves;
    } else {
      out.leftOrFirst = static_cast<uint32_t>(nodes.size());
      nodes.push_back({});
      nodes.push_back({});
      stack.push_back({n.child[1], out.leftOrFirst + 1});
      stack.push_back({n.child[0], out.leftOrFirst});
    }
    nodes[slot] = out;
  }
  bvh.nodes = std::move(nodes);
  bvh.triangleOrder = std::move(order);
  bvh.stats.nodeCount = static_cast<uint32_t>(bvh.nodes.size());
  bvh.stats.leafCount = leaves;
}

}  // namespace

ReinsertStats reinsertOptimize(Bvh& bvh, uint32_t passes, double fraction) {
  ReinsertStats stats;
  const auto start = std::chrono::steady_clock::now();
  if (isEmptyTree(bvh.nodes) || bvh.nodes.size() < 7 || passes == 0) return stats;
  Tree tree = treeOf(bvh);
  tree.stamp.assign(tree.nodes.size(), 0);
  const double rootArea = std::max(1e-30, double(area(tree.nodes[tree.root])));
  stats.areaBefore = stats.areaAfter = tree.interiorArea() / rootArea;
  std::vector<std::pair<float, uint32_t>> worst;
  for (uint32_t pass = 0; pass < passes; ++pass) {
    ++stats.passes;
    // Bittner et al.'s measure: the node's area, times its area over its smaller child's and over their mean.
    worst.clear();
    for (uint32_t i = 0; i < tree.nodes.size(); ++i) {
      const Node& n = tree.nodes[i];
      if (n.leaf() || n.parent == kNone || tree.nodes[n.parent].parent == kNone) continue;
      const float a = area(n), l = area(tree.nodes[n.child[0]]), r = area(tree.nodes[n.child[1]]);
      const float smaller = std::max(std::min(l, r), 1e-30f), mean = std::max(0.5f * (l + r), 1e-30f);
      worst.push_back({-(a * (a / smaller) * (a / mean)), i});
    }
    const size_t take = std::min(worst.size(), std::max<size_t>(1, size_t(fraction * double(worst.size()))));
    std::partial_sort(worst.begin(), worst.begin() + take, worst.end());  // ties by index: deterministic
    uint32_t moved = 0;
    for (size_t k = 0; k < take; ++k) moved += tree.reinsert(worst[k].second) ? 1u : 0u;
    if (moved == 0) break;
    ++stats.kept;
    stats.reinserted += moved;
  }
  // A move may deepen the tree; past the traversal stack's room the tree stays Embree's.
  const uint32_t depth = tree.depth();
  if (depth > kMaxBvhDepth) {
    stats.kept = stats.reinserted = 0;
  } else {
    stats.areaAfter = tree.interiorArea() / rootArea;
    layOut(tree, bvh);
    bvh.stats.maxDepth = depth;
    bvh.stats.sahCost = bvhSahCost(bvh);
  }
  stats.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return stats;
}

}  // namespace raylab
