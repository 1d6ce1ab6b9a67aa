#version 460
// Bitonic sort, the steps whose compare distance fits in a tile of SORT_BITONIC_TILE elements, done in shared
// memory with one dispatch. Mode 0 sorts each tile completely (block sizes 2 .. TILE); mode 1 finishes a
// larger merge after the global steps (half-cleaners of distance TILE/2 .. 1).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#include "spec_ids.h"
#include "sort_types.h"
#include "sort_bitonic.glsl"

layout(local_size_x_id = RL_SPEC_GROUP_SIZE) in;
layout(push_constant, scalar) uniform Push { SortBitonicPush pc; };

const uint TILE = SORT_BITONIC_TILE;
const uint TILE_LOG = SORT_BITONIC_TILE_LOG;
shared uint sKeys[TILE];
shared uint sValues[TILE];

uint tileBegin;

void compareExchange(uvec2 ij) {
  if (tileBegin + ij.y >= pc.count) return;  // virtual +infinity padding: never moves
  uint a = sKeys[ij.x], b = sKeys[ij.y];
  if (sortEffectiveKey(a, pc.keyBits) > sortEffectiveKey(b, pc.keyBits)) {
    sKeys[ij.x] = b;
    sKeys[ij.y] = a;
    uint v = sValues[ij.x];
    sValues[ij.x] = sValues[ij.y];
    sValues[ij.y] = v;
  }
}

void flipStep(uint blockLog) {
  for (uint c = gl_LocalInvocationID.x; c < TILE / 2; c += gl_WorkGroupSize.x)
    compareExchange(bitonicFlipPair(c, blockLog));
  barrier();
}

void halfStep(uint distanceLog) {
  for (uint c = gl_LocalInvocationID.x; c < TILE / 2; c += gl_WorkGroupSize.x)
    compareExchange(bitonicHalfPair(c, distanceLog));
  barrier();
}

void main() {
  tileBegin = (gl_WorkGroupID.x + pc.tileOffset) * TILE;
  // Whole tiles past the device-side bound (the live prefix) hold only dead keys, already in place.
  if (pc.hasCountLimit != 0u && tileBegin >= pc.countLimit.v[0]) return;
  for (uint j = gl_LocalInvocationID.x; j < TILE; j += gl_WorkGroupSize.x) {
    if (tileBegin + j < pc.count) {
      sKeys[j] = pc.keys.v[tileBegin + j];
      sValues[j] = pc.values.v[tileBegin + j];
    }
  }
  barrier();
  if (pc.mode == 0u) {
    for (uint blockLog = 1; blockLog <= TILE_LOG; ++blockLog) {
      flipStep(blockLog);
      for (uint d = blockLog - 1u; d > 0u; --d) halfStep(d - 1u);
    }
  } else {
    for (uint d = TILE_LOG; d > 0u; --d) halfStep(d - 1u);
  }
  for (uint j = gl_LocalInvocationID.x; j < TILE; j += gl_WorkGroupSize.x) {
    if (tileBegin + j < pc.count) {
      pc.keys.v[tileBegin + j] = sKeys[j];
      pc.values.v[tileBegin + j] = sValues[j];
    }
  }
}
