#version 460
// Inverts the sort's permutation: sortedIndices[i] = j (slot i takes path j) becomes rank[j] = i, so the
// reorder can read every path coalesced and scatter it to its new slot (writes do not stall a thread the
// way random reads do).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#include "shared_types.h"

layout(local_size_x_id = 0) in;
layout(push_constant, scalar) uniform Push {
  UintBuf sortedIndices;
  UintBuf rank;
  uint count;
  uint pad0;
} pc;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i < pc.count) pc.rank.v[pc.sortedIndices.v[i]] = i;
}
