#version 460
// Detailed statistics, distinct keys: each live key (not RL_DEAD_KEY) sets its bit in a bitmap cleared
// before the pass; a thread that finds the bit clear counts one new key. Exact whatever the order: each
// distinct value is counted by the one thread that set its bit first. Keys wider than the bitmap drop
// their lowest bits (pc.keyShift, RL_DETAIL_KEY_BITMAP_BITS). The twin: renderer/detail_sums.cpp.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#include "spec_ids.h"
#include "detail_types.h"

layout(local_size_x_id = RL_SPEC_GROUP_SIZE) in;  // RL_DETAIL_GROUP_SIZE
layout(push_constant, scalar) uniform Push { DetailPush pc; };

void main() {
  uint fresh = 0u;
  for (uint i = gl_GlobalInvocationID.x; i < pc.count; i += gl_NumWorkGroups.x * RL_DETAIL_GROUP_SIZE) {
    const uint key = pc.values.v[i];
    if (key == RL_DEAD_KEY) continue;
    const uint bit = key >> pc.keyShift;
    const uint mask = 1u << (bit & 31u);
    // A plain read first: most keys repeat (an 18-bit average key has 27k values among 8.4M paths), and an
    // atomic on a word every thread hits serializes them (H200, Sponza 4096x2048: 1.4 ms a pass). A stale read
    // only costs the atomic; the atomic alone decides what is counted.
    if ((pc.bitmap.v[bit >> 5u] & mask) != 0u) continue;
    if ((atomicOr(pc.bitmap.v[bit >> 5u], mask) & mask) == 0u) ++fresh;
  }
  fresh = subgroupAdd(fresh);
  if (subgroupElect() && fresh > 0u) atomicAdd(pc.sums.s.distinctKeys, fresh);
}
