#version 460
// Detailed statistics, virtual warp efficiency: over a trace's slots in dispatch order, each run of
// RL_VIRTUAL_WARP slots adds its traversal steps to the work and RL_VIRTUAL_WARP times its largest steps to
// the slots (a partial last warp still occupies a whole warp). The twin: renderer/detail_sums.cpp.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#include "spec_ids.h"
#include "detail_types.h"
#include "atomic_add_64.glsl"

layout(local_size_x_id = RL_SPEC_GROUP_SIZE) in;  // RL_DETAIL_GROUP_SIZE
layout(push_constant, scalar) uniform Push { DetailPush pc; };

const uint kWarps = RL_DETAIL_GROUP_SIZE / RL_VIRTUAL_WARP;
shared uint warpSteps[kWarps];
shared uint warpMax[kWarps];

void main() {
  const uint lane = gl_LocalInvocationID.x, warp = lane / RL_VIRTUAL_WARP;
  uint64_t work = 0ul, slots = 0ul;  // the group's sums, kept by lane 0
  // Every group walks whole groups of slots: the loop bound is uniform, so the barriers are too.
  for (uint base = gl_WorkGroupID.x * RL_DETAIL_GROUP_SIZE; base < pc.count;
       base += gl_NumWorkGroups.x * RL_DETAIL_GROUP_SIZE) {
    if (lane < kWarps) warpSteps[lane] = warpMax[lane] = 0u;
    barrier();
    const uint i = base + lane;
    const uint steps = i < pc.count ? pc.values.v[i] : 0u;
    atomicAdd(warpSteps[warp], steps);
    atomicMax(warpMax[warp], steps);
    barrier();
    if (lane == 0u)
      for (uint w = 0u; w < kWarps; ++w) {
        work += uint64_t(warpSteps[w]);
        slots += uint64_t(RL_VIRTUAL_WARP) * uint64_t(warpMax[w]);
      }
    barrier();
  }
  if (lane == 0u && slots > 0ul) {
    ATOMIC_ADD_64(pc.sums.s.warpWorkLo, pc.sums.s.warpWorkHi, work);
    ATOMIC_ADD_64(pc.sums.s.warpSlotsLo, pc.sums.s.warpSlotsHi, slots);
  }
}
