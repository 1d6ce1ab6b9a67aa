#version 460
// Radix sort, step (a) of a pass: the digit histogram of one work group's tiles (TILES_PER_GROUP consecutive
// ones: kDefaultRadixTilesPerGroup, 2, by default), written to the group's column of the digit-major count table (hist[digit * numGroups +
// group]). Same group size, keys per invocation and tiles as the scatter; all of an invocation's keys of a tile
// are loaded before any is counted, so the loads overlap.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_vote : require
#extension GL_KHR_shader_subgroup_ballot : require
#include "spec_ids.h"
#include "sort_types.h"

layout(local_size_x_id = RL_SPEC_GROUP_SIZE) in;
layout(constant_id = RL_SPEC_KEYS_PER_THREAD) const uint KPT = 15;  // keys per invocation
layout(constant_id = RL_SPEC_TILES_PER_GROUP) const uint TILES_PER_GROUP = 1;
layout(push_constant, scalar) uniform Push { SortRadixPush pc; };

shared uint sHist[SORT_RADIX];

void main() {
  uint t = gl_LocalInvocationID.x;
  uint group = gl_WorkGroupID.x + pc.groupOffset;
  for (uint d = t; d < SORT_RADIX; d += gl_WorkGroupSize.x) sHist[d] = 0;

  // Tiles past a device-side count limit count nothing: their column of the table is zero.
  uint count = sortLimitedCount(pc.count, pc.hasCountLimit, pc.countLimit);
  barrier();  // histogram cleared
  for (uint tile = group * TILES_PER_GROUP; tile < (group + 1) * TILES_PER_GROUP; ++tile) {
    uint begin = tile * gl_WorkGroupSize.x * KPT + t;
    if (tile * gl_WorkGroupSize.x * KPT >= count) break;  // uniform: the group's tiles past the count
    uint digits[KPT];
    for (uint k = 0; k < KPT; ++k) {
      uint i = begin + k * gl_WorkGroupSize.x;
      digits[k] = i < count ? (sortEffectiveKey(pc.keysIn.v[i], pc.keyBits) >> pc.shift) & SORT_RADIX_MASK
                               : 0xFFFFFFFFu;
    }
    for (uint k = 0; k < KPT; ++k) {
      uint d = digits[k];
      if (d == 0xFFFFFFFFu) continue;
      // Runs of equal digits (sorted or nearly constant keys, the high digits of small keys) would
      // serialise on one shared counter; a subgroup that agrees adds once.
      if (subgroupAllEqual(d)) {
        uint n = subgroupBallotBitCount(subgroupBallot(true));
        if (subgroupElect()) atomicAdd(sHist[d], n);
      } else {
        atomicAdd(sHist[d], 1u);
      }
    }
  }
  barrier();
  for (uint d = t; d < SORT_RADIX; d += gl_WorkGroupSize.x) pc.hist.v[d * pc.numGroups + group] = sHist[d];
}
