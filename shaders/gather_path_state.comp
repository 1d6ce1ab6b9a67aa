#version 460
// Gathers every path-state array of the current set (48 bytes a path, path_state.glsl's movePath; 76
// before radiance went to results and alive into the path id) through the sorted indices into the other set, so
// the next bounce reads coherent memory (indexing through the permutation without moving the data made
// the study's tracer slower). A gather (random reads, coalesced writes): the scatter through the inverse
// permutation was measured slower on an H100 (2.81 against 1.49 ms a frame, hall, 2048x1024, two-point
// keys). Only the live prefix is moved; the slots behind it are marked finished so no stale state from an
// earlier bounce looks alive to the stages that read every slot (learn, the detailed captures).
// It also finds the live prefix's length (GpuFrame::live and the indirect dispatch size of the next trace
// and shade): the sorted keys put every finished path (RL_DEAD_KEY) behind the live ones, so slot i is live
// exactly when its sorted key is not dead. This was a pass of its own (live_count) before the gather read
// the keys; folded in, the reorder is one dispatch and one barrier shorter.
// The slot's work is reorder_slot.glsl's, which the gathering trace (Settings::fusion gather) shares.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#include "spec_ids.h"
#include "shared_types.h"
#include "live_paths.glsl"
#include "path_state.glsl"
#include "reorder_slot.glsl"
#include "dispatch_index.glsl"

layout(local_size_x_id = RL_SPEC_GROUP_SIZE) in;
layout(push_constant, scalar) uniform Push { PathStagePush pc; };

void main() {
  uint i = flatInvocationIndex();
  GpuFrame f = FrameBuf(pc.frame).f;
  if (i >= f.pathCount) return;
  vec3 origin, direction;
  reorderSlot(f, pc.stateSet, i, origin, direction);
}
