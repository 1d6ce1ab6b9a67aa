#version 460
// Radix sort, step (b) of a pass: the work group of a digit turns its row of per-tile counts into exclusive
// prefixes (where the tile's run of that digit starts among all keys with the digit) and stores the
// digit's total after the table, for the scatter to scan across digits. No group waits on another.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#include "spec_ids.h"
#include "sort_types.h"

layout(local_size_x_id = RL_SPEC_GROUP_SIZE) in;
layout(push_constant, scalar) uniform Push { SortScanPush pc; };

#include "sort_scan.glsl"

const uint PER_THREAD = 4;  // consecutive counters per invocation: fewer barriers per row

void scanRow(uint digit) {
  uint row = digit * pc.numGroups;
  uint n = pc.numGroups;
  uint carry = 0;
  for (uint base = 0; base < n; base += gl_WorkGroupSize.x * PER_THREAD) {
    uint first = base + gl_LocalInvocationID.x * PER_THREAD;
    uint v[PER_THREAD];
    uint sum = 0;
    for (uint k = 0; k < PER_THREAD; ++k) {
      v[k] = first + k < n ? pc.hist.v[row + first + k] : 0u;
      sum += v[k];
    }
    uint total;
    uint prefix = carry + groupExclusiveAdd(sum, total);
    for (uint k = 0; k < PER_THREAD; ++k) {
      if (first + k < n) pc.hist.v[row + first + k] = prefix;
      prefix += v[k];
    }
    carry += total;
  }
  if (gl_LocalInvocationID.x == 0) pc.hist.v[SORT_RADIX * n + digit] = carry;
}

void main() {
  for (uint r = 0; r < pc.rowsPerGroup; ++r) scanRow(gl_WorkGroupID.x * pc.rowsPerGroup + r);
}
