// The live-path count and its indirect dispatch size (GpuFrame::live, the RL_LIVE_* slots), written the
// same way by generate.comp (every path) and gather_path_state.comp (the live prefix after a sort).
#ifndef RAYLAB_LIVE_PATHS_GLSL
#define RAYLAB_LIVE_PATHS_GLSL

#include "shared_types.h"

void writeLivePaths(UintBuf live, uint n) {
  live.v[RL_LIVE_COUNT] = n;
  live.v[RL_LIVE_DISPATCH + 0u] = (n + RL_PATH_GROUP_SIZE - 1u) / RL_PATH_GROUP_SIZE;
  live.v[RL_LIVE_DISPATCH + 1u] = 1u;
  live.v[RL_LIVE_DISPATCH + 2u] = 1u;
}

#endif
