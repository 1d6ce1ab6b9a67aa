// The live-path count and its indirect dispatch size (GpuFrame::live, the RL_LIVE_* slots), written the
// same way by generate.comp (every path) and gather_path_state.comp (the live prefix after a sort).
#ifndef RAYLAB_LIVE_PATHS_GLSL
#define RAYLAB_LIVE_PATHS_GLSL

#include "shared_types.h"
#include "dispatch_index.glsl"

void writeLivePaths(GpuFrame f, uint n) {
  uvec3 groups = dispatchGridFor(n, RL_PATH_GROUP_SIZE, f.dispatchRowGroups);
  f.live.v[RL_LIVE_COUNT] = n;
  f.live.v[RL_LIVE_DISPATCH + 0u] = groups.x;
  f.live.v[RL_LIVE_DISPATCH + 1u] = groups.y;
  f.live.v[RL_LIVE_DISPATCH + 2u] = groups.z;
}

#endif
