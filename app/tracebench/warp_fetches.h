// What a warp reads from memory when its lanes traverse together, counted on the CPU: every ray of a set walked
// by the twin of the GPU's pair-node traversal (traversePairsCpu) in the order the GPU's threads take them,
// 32 consecutive rays a warp. Sorting rays lowers the steps a warp waits for (the warp efficiency tracebench
// reports); whether it also lowers the reads that reach the caches, and how many distinct bytes the rays the GPU
// holds at once touch, is what these count. Counts, not times: what a cache makes of them is the device's.
#pragma once

#include <cstdint>

#include "app/tracebench/trace_rays.h"
#include "renderer/gpu_scene.h"
#include "shaders/detail_types.h"

namespace raylab {

// The threads an H200 holds at once (132 multiprocessors, 2,048 threads each): the rays whose reads meet in
// its L2 (50 MB) while they trace.
constexpr uint32_t kH200ResidentThreads = 132u * 2048u;
constexpr uint32_t kWarpSize = RL_VIRTUAL_WARP;  // the warps the detailed figures count
// Bytes a read: a pair node (BvhPairNode) and a leaf entry (GpuLeafTriangle).
constexpr uint32_t kPairNodeBytes = 64, kLeafEntryBytes = 48;

struct FetchCounts {
  double meanSteps = 0;                               // the twin's steps a ray (the GPU's mean_steps)
  double nodesPerRay = 0, entriesPerRay = 0;          // each lane's own reads: pair nodes and leaf entries
  double warpNodesPerRay = 0, warpEntriesPerRay = 0;  // distinct reads of each warp (32 consecutive rays), a ray
  // The loads a warp issues when its lanes run the loop in lockstep (iteration k of the warp is every active
  // lane's step k, and a leaf's entry j every lane's entry j in that leaf): the distinct reads of each such
  // iteration, a ray. Lanes reading the same thing in the same iteration share a load; a read shared only across
  // iterations is a load each time (which the L1 may serve).
  double requestNodesPerRay = 0, requestEntriesPerRay = 0;
  // Distinct bytes the rays of a window of `window` consecutive rays read, megabytes, averaged over the set's
  // whole windows (the set itself when it is smaller than one window).
  double windowMegabytes = 0;
};

// `anyHit`: shadow rays' traversal (stops at a hit). Runs on the hardware's threads; the counts do not depend
// on how many. `window` is rounded down to whole warps (at least one); 0 throws std::invalid_argument.
FetchCounts countFetches(const HostPairTree& tree, const RaySet& rays, bool anyHit,
                         uint32_t window = kH200ResidentThreads);

}  // namespace raylab
