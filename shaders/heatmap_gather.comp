#version 460
// Writes the heatmap value of each path's first sample to its pixel, for the bounce being shown, and
// widens the value range for the legend. Runs right after the trace (or key stage) of that bounce.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#include "heatmap_types.h"
#include "rng.glsl"
#include "keys.glsl"
#include "path_state.glsl"

layout(local_size_x_id = 0) in;
layout(push_constant, scalar) uniform Push { HeatmapPush pc; };

// Efficiency of the 32-wide warp holding path slot i: sum(steps) / (32 * max steps), as DESIGN.md defines.
float warpEfficiency(GpuFrame f, uint i) {
  uint first = i & ~31u;
  uint sum = 0u, mx = 0u;
  for (uint k = first; k < min(first + 32u, f.pathCount); ++k) {
    uint s = f.hits.steps.v[k];
    sum += s;
    mx = max(mx, s);
  }
  return mx > 0u ? float(sum) / (32.0 * float(mx)) : 1.0;
}

float cacheValue(GpuKeyParams P, vec3 origin, vec3 dir, bool variance) {
  int e = cacheEntry(P.cache, P.grid, cellOf(P.grid, origin), dir);
  if (e < 0) return -1.0;
  GpuCacheEntry c = P.cache.entries.v[e];
  if (c.count == 0u) return -1.0;
  return variance ? (c.count > 1u ? c.m2 / float(c.count - 1u) : 0.0) : c.mean;
}

void main() {
  GpuFrame f = FrameBuf(pc.frame).f;
  uint i = gl_GlobalInvocationID.x;
  if (i >= f.pathCount) return;
  GpuPathState s = f.state[pc.stateSet];
  uint id = pc.megakernel != 0u ? i : pathId(s, i);
  bool alive = pc.megakernel != 0u || (i < f.live.v[RL_LIVE_COUNT] && id != RL_DEAD_PATH);
  if (!alive || id % f.sppPerFrame != 0u) return;
  uint pixel = id / f.sppPerFrame;
  float value = -1.0;
  uint bits;
  if (pc.view == RL_HEAT_SORT_KEY) {
    bits = pc.keys.v[i];
    if (bits == RL_DEAD_KEY) return;
    pc.heat.v[pixel] = bits;
    atomicMin(pc.range.v[0], bits);
    atomicMax(pc.range.v[1], bits);
    return;
  }
  vec3 o = pathOrigin(s, i), d = pathDirection(s, i);
  if (pc.view == RL_HEAT_STEPS) value = float(f.hits.steps.v[i]);
  else if (pc.view == RL_HEAT_WARP) value = warpEfficiency(f, i);
  else if (pc.hasKeyParams != 0u) {
    GpuKeyParams P = pc.keyParams.p;
    if (pc.view == RL_HEAT_CELL_HIT) {
      float predicted = pathPredictedLength(s, i), t = f.hits.t.v[i];
      if (predicted >= 0.0 && t > 0.0) value = all(equal(cellOf(P.grid, o + predicted * d), cellOf(P.grid, o + t * d))) ? 1.0 : 0.0;
    } else if (pc.hasCache != 0u) {  // without a cache its addresses are null: never follow them
      value = cacheValue(P, o, d, pc.view == RL_HEAT_CACHE_VARIANCE);
    }
  }
  if (!(value >= 0.0)) return;  // no data (or NaN): the pixel stays empty
  bits = floatBitsToUint(value);  // non-negative floats order like their bits
  pc.heat.v[pixel] = bits;
  atomicMin(pc.range.v[0], bits);
  atomicMax(pc.range.v[1], bits);
}
