#version 460
// Bitonic sort, one step whose compare distance spans tiles: one compare-exchange per invocation, a
// grid-stride loop so any count fits the device's group-count limit.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#include "spec_ids.h"
#include "sort_types.h"
#include "sort_bitonic.glsl"

layout(local_size_x_id = RL_SPEC_GROUP_SIZE) in;
layout(push_constant, scalar) uniform Push { SortBitonicPush pc; };

void main() {
  uint stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
  for (uint c = gl_GlobalInvocationID.x; c < pc.comparators; c += stride) {
    uvec2 ij = pc.mode == 0u ? bitonicFlipPair(c, pc.blockLog) : bitonicHalfPair(c, pc.distanceLog);
    if (ij.y >= pc.count) continue;  // virtual +infinity padding: never moves
    uint a = pc.keys.v[ij.x], b = pc.keys.v[ij.y];
    if (sortEffectiveKey(a, pc.keyBits) > sortEffectiveKey(b, pc.keyBits)) {
      pc.keys.v[ij.x] = b;
      pc.keys.v[ij.y] = a;
      uint v = pc.values.v[ij.x];
      pc.values.v[ij.x] = pc.values.v[ij.y];
      pc.values.v[ij.y] = v;
    }
  }
}
