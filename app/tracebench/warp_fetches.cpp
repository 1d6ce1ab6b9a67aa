#include "app/tracebench/warp_fetches.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <vector>

#include "renderer/bvh/bvh_traverse_cpu.h"
#include "renderer/parallel.h"

namespace raylab {
namespace {

// A set of node or entry indices seen since the last mark: each index remembers the mark it was last seen under,
// so a new warp or window starts empty without clearing anything.
class SeenSince {
 public:
  explicit SeenSince(size_t size) : mark_(size, kNever) {}
  // True the first time `index` is seen under `mark`.
  bool first(uint32_t index, uint32_t mark) {
    if (mark_[index] == mark) return false;
    mark_[index] = mark;
    return true;
  }

 private:
  static constexpr uint32_t kNever = std::numeric_limits<uint32_t>::max();
  std::vector<uint32_t> mark_;
};

// One window's sums (the rays [begin, end)), in task order.
struct WindowSums {
  uint64_t steps = 0, nodes = 0, entries = 0, warpNodes = 0, warpEntries = 0, windowBytes = 0;
  uint64_t requestNodes = 0, requestEntries = 0;
};

// The distinct values of a few (at most a warp's).
uint32_t distinctCount(std::vector<uint32_t>& values) {
  std::sort(values.begin(), values.end());
  return static_cast<uint32_t>(std::unique(values.begin(), values.end()) - values.begin());
}

// The loads of one warp's lanes in lockstep (FetchCounts::requestNodesPerRay): at each step, the distinct pair
// nodes of the lanes visiting one, then for each entry j of a leaf the distinct entries of the lanes in a leaf.
void countRequests(const std::vector<PairFetchLog>& lanes, uint32_t laneCount, WindowSums& sums) {
  size_t longest = 0;
  for (uint32_t l = 0; l < laneCount; ++l) longest = std::max(longest, lanes[l].steps.size());
  std::vector<uint32_t> nodes, entries;
  for (size_t k = 0; k < longest; ++k) {
    nodes.clear();
    uint32_t mostEntries = 0;
    for (uint32_t l = 0; l < laneCount; ++l) {
      if (k >= lanes[l].steps.size()) continue;
      const uint32_t word = lanes[l].steps[k];
      if (word < RL_LEAF_TAG) nodes.push_back(word);
      else mostEntries = std::max(mostEntries, RL_LEAF_COUNT(word));
    }
    sums.requestNodes += distinctCount(nodes);
    for (uint32_t j = 0; j < mostEntries; ++j) {
      entries.clear();
      for (uint32_t l = 0; l < laneCount; ++l)
        if (k < lanes[l].steps.size() && lanes[l].steps[k] >= RL_LEAF_TAG && j < RL_LEAF_COUNT(lanes[l].steps[k]))
          entries.push_back(RL_LEAF_FIRST(lanes[l].steps[k]) + j);
      sums.requestEntries += distinctCount(entries);
    }
  }
}

WindowSums countWindow(const HostPairTree& tree, const RaySet& rays, bool anyHit, uint32_t begin, uint32_t end) {
  WindowSums sums;
  SeenSince warpNodes(tree.nodes.size()), warpEntries(tree.entries.size());
  SeenSince windowNodes(tree.nodes.size()), windowEntries(tree.entries.size());
  std::vector<PairFetchLog> lanes(kWarpSize);
  for (uint32_t warpBegin = begin; warpBegin < end; warpBegin += kWarpSize) {
    const uint32_t warp = warpBegin / kWarpSize;
    const uint32_t laneCount = std::min(kWarpSize, end - warpBegin);
    for (uint32_t l = 0; l < laneCount; ++l) {
      const uint32_t i = warpBegin + l;
      PairFetchLog& log = lanes[l];
      log.steps.clear();
      const CpuHit hit = traversePairsCpu(tree.nodes, tree.entries, glm::vec3(rays.origins[i]),
                                          glm::vec3(rays.directions[i]), rays.directions[i].w, anyHit, &log);
      sums.steps += hit.steps;
      sums.nodes += hit.nodeVisits;
      sums.entries += hit.triangleTests;
      for (uint32_t word : log.steps) {
        if (word < RL_LEAF_TAG) {
          sums.warpNodes += warpNodes.first(word, warp);
          sums.windowBytes += windowNodes.first(word, 0) ? kPairNodeBytes : 0;
          continue;
        }
        for (uint32_t e = RL_LEAF_FIRST(word); e < RL_LEAF_FIRST(word) + RL_LEAF_COUNT(word); ++e) {
          sums.warpEntries += warpEntries.first(e, warp);
          sums.windowBytes += windowEntries.first(e, 0) ? kLeafEntryBytes : 0;
        }
      }
    }
    countRequests(lanes, laneCount, sums);
  }
  return sums;
}

}  // namespace

FetchCounts countFetches(const HostPairTree& tree, const RaySet& rays, bool anyHit, uint32_t window) {
  if (window == 0) throw std::invalid_argument("countFetches: a window of 0 rays");
  FetchCounts c;
  const uint32_t n = rays.size();
  if (n == 0) return c;
  // Windows start on a warp (so no warp is split between two tasks); the tail beyond the last whole window is
  // counted in the per-ray figures but not in the windows' bytes.
  const uint32_t windowRays = std::max(kWarpSize, window / kWarpSize * kWarpSize);
  const uint32_t whole = n / windowRays;
  const uint32_t tasks = whole + (n % windowRays != 0);
  std::vector<WindowSums> sums(tasks);
  parallelFor(workerThreads(0, tasks, 1), tasks, [&](size_t t) {
    const uint32_t begin = static_cast<uint32_t>(t) * windowRays;
    sums[t] = countWindow(tree, rays, anyHit, begin, std::min(n, begin + windowRays));
  });
  WindowSums total;
  for (uint32_t t = 0; t < tasks; ++t) {
    total.steps += sums[t].steps, total.nodes += sums[t].nodes, total.entries += sums[t].entries;
    total.warpNodes += sums[t].warpNodes, total.warpEntries += sums[t].warpEntries;
    total.requestNodes += sums[t].requestNodes, total.requestEntries += sums[t].requestEntries;
    if (t < std::max(whole, 1u)) total.windowBytes += sums[t].windowBytes;
  }
  c.meanSteps = double(total.steps) / n;
  c.nodesPerRay = double(total.nodes) / n;
  c.entriesPerRay = double(total.entries) / n;
  c.warpNodesPerRay = double(total.warpNodes) / n;
  c.warpEntriesPerRay = double(total.warpEntries) / n;
  c.requestNodesPerRay = double(total.requestNodes) / n;
  c.requestEntriesPerRay = double(total.requestEntries) / n;
  c.windowMegabytes = double(total.windowBytes) / std::max(whole, 1u) * 1e-6;
  return c;
}

}  // namespace raylab
