#version 460
// The whole sort of a small count (<= SORT_SMALL_MAX) in one work group and one dispatch (GpuSorter, below its
// small-sort threshold): the pairs are loaded into shared memory, sorted there by the bitonic network of
// sort_bitonic.glsl over the next power of two (padding past the count is virtual +infinity and never moves),
// and written back in place. Stable: it compares (effective key >> ignoredLowBits, input index), a total
// order that is exactly the stable order the radix sort produces.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#include "spec_ids.h"
#include "sort_types.h"
#include "sort_bitonic.glsl"

layout(local_size_x_id = RL_SPEC_GROUP_SIZE) in;
layout(push_constant, scalar) uniform Push { SortSmallPush pc; };

shared uint sKeys[SORT_SMALL_MAX];
shared uint sValues[SORT_SMALL_MAX];
shared uint sIndex[SORT_SMALL_MAX];

uint n;

uint compared(uint slot) { return sortEffectiveKey(sKeys[slot], pc.keyBits) >> pc.ignoredLowBits; }

void compareExchange(uvec2 ij) {
  if (ij.y >= n) return;  // virtual +infinity padding: never moves
  uint a = compared(ij.x), b = compared(ij.y);
  if (a > b || (a == b && sIndex[ij.x] > sIndex[ij.y])) {
    uint k = sKeys[ij.x];
    sKeys[ij.x] = sKeys[ij.y];
    sKeys[ij.y] = k;
    uint v = sValues[ij.x];
    sValues[ij.x] = sValues[ij.y];
    sValues[ij.y] = v;
    uint i = sIndex[ij.x];
    sIndex[ij.x] = sIndex[ij.y];
    sIndex[ij.y] = i;
  }
}

void main() {
  n = sortLimitedCount(min(pc.count, SORT_SMALL_MAX), pc.hasCountLimit, pc.countLimit);
  for (uint j = gl_LocalInvocationID.x; j < n; j += gl_WorkGroupSize.x) {
    sKeys[j] = pc.keys.v[j];
    sValues[j] = pc.values.v[j];
    sIndex[j] = j;
  }
  barrier();
  // The network over the next power of two of n: 2^log >= n (log 0 for n <= 1: nothing to do).
  uint log = n <= 1u ? 0u : findMSB(n - 1u) + 1u;
  uint comparators = (1u << log) / 2u;
  for (uint blockLog = 1u; blockLog <= log; ++blockLog) {
    for (uint c = gl_LocalInvocationID.x; c < comparators; c += gl_WorkGroupSize.x)
      compareExchange(bitonicFlipPair(c, blockLog));
    barrier();
    for (uint d = blockLog - 1u; d > 0u; --d) {
      for (uint c = gl_LocalInvocationID.x; c < comparators; c += gl_WorkGroupSize.x)
        compareExchange(bitonicHalfPair(c, d - 1u));
      barrier();
    }
  }
  for (uint j = gl_LocalInvocationID.x; j < n; j += gl_WorkGroupSize.x) {
    pc.keys.v[j] = sKeys[j];
    pc.values.v[j] = sValues[j];
  }
}
