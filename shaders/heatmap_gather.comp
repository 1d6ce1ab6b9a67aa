#version 460
// Writes the heatmap value of each path's first sample to its pixel, for the bounce being shown, with what
// the hover readout shows (path id, key, cell), and widens the value range and counts for the legend. Runs
// right after the trace (or key stage) of that bounce; for sort keys by rank, once more after the sort.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#include "spec_ids.h"
#include "heatmap_types.h"
#include "rng.glsl"
#include "keys.glsl"
#include "path_state.glsl"
#include "heatmap_colours.glsl"
#include "dispatch_index.glsl"
#include "camera_order.h"

layout(local_size_x_id = RL_SPEC_GROUP_SIZE) in;
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

// The cached length statistic at the ray's (origin cell, octant); negative when that entry is empty.
float cacheValue(GpuKeyParams P, vec3 origin, vec3 dir, bool variance) {
  int e = cacheEntry(P.cache, P.grid, cellOf(P.grid, origin), dir);
  if (e < 0) return -1.0;
  GpuCacheEntry c = P.cache.entries.v[e];
  if (c.count == 0u) return -1.0;
  return variance ? (c.count > 1u ? c.m2 / float(c.count - 1u) : 0.0) : c.mean;
}

void widenRange(uint bits) {
  atomicMin(pc.range.v[RL_HEAT_RANGE_MIN], bits);
  atomicMax(pc.range.v[RL_HEAT_RANGE_MAX], bits);
  atomicAdd(pc.range.v[RL_HEAT_RANGE_VALUES], 1u);
}

void writeProbe(uint pixel, uint id, uint key, uint cell, uint oct) {
  uint p = pixel * RL_HEAT_PROBE_STRIDE;
  pc.probe.v[p + RL_HEAT_PROBE_PATH] = id;
  pc.probe.v[p + RL_HEAT_PROBE_KEY] = key;
  pc.probe.v[p + RL_HEAT_PROBE_CELL] = cell;
  pc.probe.v[p + RL_HEAT_PROBE_OCTANT] = oct;
}

// The cell the probe shows for a sort key: direction keys pack (u, v) 16 bits each, grid cells 10 bits an axis.
uint keyProbeCell(GpuKeyParams P, uint key) {
  uvec3 cells;
  uvec3 c = keyCell(pc.strategy, P.grid, key, cells);
  return pc.strategy == RL_KEY_DIRECTION ? (c.x | (c.y << 16)) : packCell(c);
}

void main() {
  GpuFrame f = FrameBuf(pc.frame).f;
  uint i = flatInvocationIndex();
  if (i >= f.pathCount) return;
  GpuPathState s = f.state[pc.stateSet];
  // The megakernel's slot i holds the path generate puts there (camera_order.h).
  uint id = pc.megakernel != 0u ? cameraPathOfSlot(i, f.width, f.height, f.sppPerFrame) : pathId(s, i);
  bool alive = pc.megakernel != 0u || (i < f.live.v[RL_LIVE_COUNT] && id != RL_DEAD_PATH);
  if (!alive || id % f.sppPerFrame != 0u) return;
  uint pixel = id / f.sppPerFrame;
  if (pc.gather == RL_HEAT_GATHER_RANK) {
    // The sort put the paths in key order: slot i holds the key of rank i among the live paths.
    uint bits = floatBitsToUint(float(i));
    pc.heat.v[pixel] = bits;
    widenRange(bits);
    return;
  }
  if (pc.view == RL_HEAT_SORT_KEY) {
    uint key = pc.keys.v[i];
    if (key == RL_DEAD_KEY) return;
    writeProbe(pixel, id, key, pc.hasKeyParams != 0u ? keyProbeCell(pc.keyParams.p, key) : RL_HEAT_NO_CELL,
               octant(pathDirection(s, i)));
    if (pc.keyColour == RL_HEAT_KEY_RANK) return;  // the rank gather after the sort writes the value
    if (pc.keyColour == RL_HEAT_KEY_CELL && pc.hasKeyParams != 0u) {
      uvec3 cells;
      uvec3 c = keyCell(pc.strategy, pc.keyParams.p.grid, key, cells);
      for (uint a = 0u; a < 3u; ++a) {
        atomicMin(pc.range.v[RL_HEAT_RANGE_CELL_MIN + a], c[a]);
        atomicMax(pc.range.v[RL_HEAT_RANGE_CELL_MAX + a], c[a]);
      }
    }
    pc.heat.v[pixel] = key;
    widenRange(key);
    return;
  }
  float value = -1.0;
  uint cell = RL_HEAT_NO_CELL;
  vec3 o = pathOrigin(s, i), d = pathDirection(s, i);
  if (pc.view == RL_HEAT_STEPS) value = float(f.hits.steps.v[i]);
  else if (pc.view == RL_HEAT_WARP) value = warpEfficiency(f, i);
  if (pc.hasKeyParams != 0u) {
    GpuKeyParams P = pc.keyParams.p;
    cell = packCell(cellOf(P.grid, o));
    if (pc.view == RL_HEAT_CELL_HIT) {
      float predicted = pathPredictedLength(s, i), t = f.hits.t.v[i];
      if (predicted >= 0.0 && t > 0.0) value = all(equal(cellOf(P.grid, o + predicted * d), cellOf(P.grid, o + t * d))) ? 1.0 : 0.0;
    } else if ((pc.view == RL_HEAT_CACHE_MEAN || pc.view == RL_HEAT_CACHE_VARIANCE) && pc.hasCache != 0u) {
      // Without a cache its addresses are null: never follow them.
      value = cacheValue(P, o, d, pc.view == RL_HEAT_CACHE_VARIANCE);
    }
  }
  writeProbe(pixel, id, RL_DEAD_KEY, cell, octant(d));
  if (!(value >= 0.0)) {  // the path is here but has no value (empty cache entry, escaped ray, NaN)
    pc.heat.v[pixel] = RL_HEAT_NO_VALUE;
    atomicAdd(pc.range.v[RL_HEAT_RANGE_NO_VALUE], 1u);
    return;
  }
  uint bits = floatBitsToUint(value);  // non-negative floats order like their bits
  pc.heat.v[pixel] = bits;
  widenRange(bits);
}
