#version 460
// Detailed statistics, length-cache occupancy: the entries holding samples (count > 0), at the end of the
// frame. The twin: renderer/detail_sums.cpp.
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
  GpuLengthCache cache = KeyParamsBuf(pc.keyParams).p.cache;
  uint used = 0u;
  for (uint i = gl_GlobalInvocationID.x; i < pc.count; i += gl_NumWorkGroups.x * RL_DETAIL_GROUP_SIZE)
    if (cache.entries.v[i].count > 0u) ++used;
  used = subgroupAdd(used);
  if (subgroupElect() && used > 0u) atomicAdd(pc.sums.s.cacheUsed, used);
}
