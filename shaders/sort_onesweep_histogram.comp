#version 460
// OneSweep radix sort, before the passes: the digit histograms of every pass in one read of the keys,
// accumulated per work group in shared memory and added to the global histograms with atomics.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_vote : require
#extension GL_KHR_shader_subgroup_ballot : require
#include "spec_ids.h"
#include "sort_types.h"

layout(local_size_x_id = RL_SPEC_GROUP_SIZE) in;
layout(push_constant, scalar) uniform Push { SortOneSweepPush pc; };

const uint KPT = SORT_ONESWEEP_HIST_KPT;
shared uint sHist[SORT_ONESWEEP_MAX_PASSES * SORT_RADIX];

void count(uint bin) {
  // Equal digits across a subgroup (sorted keys, the top digits of small keys) would serialise on one counter.
  if (subgroupAllEqual(bin)) {
    uint n = subgroupBallotBitCount(subgroupBallot(true));
    if (subgroupElect()) atomicAdd(sHist[bin], n);
  } else {
    atomicAdd(sHist[bin], 1u);
  }
}

void main() {
  uint t = gl_LocalInvocationID.x;
  uint bins = pc.passes * SORT_RADIX;
  for (uint i = t; i < bins; i += gl_WorkGroupSize.x) sHist[i] = 0;
  barrier();
  uint chunk = gl_WorkGroupSize.x * KPT;
  // Only the pairs the passes sort (pc.count, or the device-side bound below it).
  uint n = sortLimitedCount(pc.count, pc.hasCountLimit, pc.countLimit);
  // Grid-stride over chunks, so any count fits the device's group-count limit.
  for (uint begin = gl_WorkGroupID.x * chunk; begin < n; begin += gl_NumWorkGroups.x * chunk) {
    uint keys[KPT];
    for (uint k = 0; k < KPT; ++k) {
      uint i = begin + k * gl_WorkGroupSize.x + t;
      keys[k] = i < n ? sortEffectiveKey(pc.keysIn.v[i], pc.keyBits) >> pc.shift : 0u;
    }
    for (uint k = 0; k < KPT; ++k) {
      if (begin + k * gl_WorkGroupSize.x + t >= n) continue;
      for (uint p = 0; p < pc.passes; ++p) count(p * SORT_RADIX + ((keys[k] >> (p * SORT_RADIX_BITS)) & SORT_RADIX_MASK));
    }
  }
  barrier();
  for (uint i = t; i < bins; i += gl_WorkGroupSize.x)
    if (sHist[i] != 0u) atomicAdd(pc.state.v[i], sHist[i]);
}
