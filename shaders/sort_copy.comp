#version 460
// Copies keys and values back into the caller's buffers after an odd number of radix passes (the sorter
// only has device addresses of the caller's buffers, so vkCmdCopyBuffer is not an option).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#include "spec_ids.h"
#include "sort_types.h"

layout(local_size_x_id = RL_SPEC_GROUP_SIZE) in;
layout(push_constant, scalar) uniform Push { SortCopyPush pc; };

void main() {
  uint stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
  uint count = sortLimitedCount(pc.count, pc.hasCountLimit, pc.countLimit);  // pairs past a limit stay put
  for (uint i = gl_GlobalInvocationID.x; i < count; i += stride) {
    pc.keysOut.v[i] = pc.keysIn.v[i];
    pc.valuesOut.v[i] = pc.valuesIn.v[i];
  }
}
