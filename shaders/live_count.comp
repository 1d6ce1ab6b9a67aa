#version 460
// After a sort that put finished paths (RL_DEAD_KEY) behind the live ones: the live prefix's length and
// the indirect dispatch size, so later stages of this frame visit only live paths.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#include "shared_types.h"
#include "live_paths.glsl"

layout(local_size_x_id = 0) in;
layout(push_constant, scalar) uniform Push { LiveCountPush pc; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= pc.count) return;
  bool here = pc.sortedKeys.v[i] != RL_DEAD_KEY;
  if (i == 0u && !here) writeLivePaths(pc.live, 0u);
  // Exactly one thread sees the boundary between the last live and the first finished path.
  if (here && (i + 1u == pc.count || pc.sortedKeys.v[i + 1u] == RL_DEAD_KEY)) writeLivePaths(pc.live, i + 1u);
}
