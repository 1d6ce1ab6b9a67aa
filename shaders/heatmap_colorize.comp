#version 460
// Heatmap values to display colours (heatmap_colours.glsl): sort keys by the cell they encode, their rank
// or a hash; cell hits green/red; everything else through the ramp over the colour range (locked, the
// view's natural one, or the frame's), linear or log. Pixels without a path, and paths without a value
// (an empty cache entry), get colours of their own.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#include "spec_ids.h"
#include "heatmap_types.h"
#include "rng.glsl"
#include "heatmap_colours.glsl"
#include "dispatch_index.glsl"

layout(local_size_x_id = RL_SPEC_GROUP_SIZE) in;
layout(push_constant, scalar) uniform Push { HeatmapPush pc; };

void main() {
  GpuFrame f = FrameBuf(pc.frame).f;
  uint pixel = flatInvocationIndex();
  if (pixel >= f.width * f.height) return;
  uint bits = pc.heat.v[pixel];
  vec3 c;
  if (bits == RL_HEAT_EMPTY) {
    c = noPathColour();
  } else if (bits == RL_HEAT_NO_VALUE) {
    c = noValueColour();
  } else if (pc.view == RL_HEAT_SORT_KEY && pc.keyColour == RL_HEAT_KEY_HASH) {
    c = hashColour(bits);
  } else if (pc.view == RL_HEAT_SORT_KEY && pc.keyColour == RL_HEAT_KEY_CELL) {
    uvec3 cells = uvec3(1u);
    uvec3 cell = pc.hasKeyParams != 0u ? keyCell(pc.strategy, pc.keyParams.p.grid, bits, cells) : uvec3(0u);
    uvec3 lo = uvec3(pc.range.v[RL_HEAT_RANGE_CELL_MIN], pc.range.v[RL_HEAT_RANGE_CELL_MIN + 1u], pc.range.v[RL_HEAT_RANGE_CELL_MIN + 2u]);
    uvec3 hi = uvec3(pc.range.v[RL_HEAT_RANGE_CELL_MAX], pc.range.v[RL_HEAT_RANGE_CELL_MAX + 1u], pc.range.v[RL_HEAT_RANGE_CELL_MAX + 2u]);
    c = stretchedCellColour(cell, lo, hi);
  } else if (pc.view == RL_HEAT_CELL_HIT) {
    c = cellHitColour(uintBitsToFloat(bits) > 0.5);
  } else {  // scalar views, and sort-key ranks (bits: the rank as a float)
    float lo = pc.rangeFixed != 0u ? pc.rangeMin : uintBitsToFloat(pc.range.v[RL_HEAT_RANGE_MIN]);
    float hi = pc.rangeFixed != 0u ? pc.rangeMax : uintBitsToFloat(pc.range.v[RL_HEAT_RANGE_MAX]);
    c = heatmapRamp(heatmapT(uintBitsToFloat(bits), lo, hi, pc.logScale != 0u));
  }
  f.image.v[pixel] = packColour(c);
}
