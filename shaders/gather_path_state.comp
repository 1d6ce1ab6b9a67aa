#version 460
// Gathers every path-state array of the current set (48 bytes a path, path_state.glsl's copyPath; 76
// before radiance went to results and alive into the path id) through the sorted indices into the other set, so
// the next bounce reads coherent memory (indexing through the permutation without moving the data made
// the study's tracer slower). A gather (random reads, coalesced writes): the scatter through the inverse
// permutation was measured slower on an H100 (2.81 against 1.49 ms a frame, hall, 2048x1024, two-point
// keys). Only the live prefix (GpuFrame::live, after the sort) is moved; the slots
// behind it are marked finished so no stale state from an earlier bounce looks alive to the key stage.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#include "shared_types.h"
#include "path_state.glsl"

layout(local_size_x_id = 0) in;
layout(push_constant, scalar) uniform Push { GatherPush pc; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= pc.count) return;
  GpuFrame f = pc.frame.f;
  GpuPathState dst = f.state[1u - pc.stateSet];
  if (i >= f.live.v[RL_LIVE_COUNT]) {
    markPathFinished(dst, i);
    return;
  }
  copyPath(dst, i, f.state[pc.stateSet], pc.sortedIndices.v[i]);
}
