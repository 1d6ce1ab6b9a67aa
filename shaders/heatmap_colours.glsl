// Heatmap values to colours; each function is the twin of the one of the same name in
// renderer/heatmap/heatmap_colours.cpp (tests/gpu/heatmap/test_heatmap_colours.cpp compares the two on the GPU's output).
// Needs heatmap_types.h and rng.glsl.
#ifndef RAYLAB_HEATMAP_COLOURS_GLSL
#define RAYLAB_HEATMAP_COLOURS_GLSL

// Polynomial fit of the Turbo colour map (Mikhailov 2019), t in [0, 1].
vec3 heatmapRamp(float t) {
  const vec4 r4 = vec4(0.13572138, 4.61539260, -42.66032258, 132.13108234);
  const vec4 g4 = vec4(0.09140261, 2.19418839, 4.84296658, -14.18503333);
  const vec4 b4 = vec4(0.10667330, 12.64194608, -60.58204836, 110.36276771);
  const vec2 r2 = vec2(-152.94239396, 59.28637943);
  const vec2 g2 = vec2(4.27729857, 2.82956604);
  const vec2 b2 = vec2(-89.90310912, 27.34824973);
  float x = clamp(t, 0.0, 1.0);
  vec4 v4 = vec4(1.0, x, x * x, x * x * x);
  vec2 v2 = v4.zw * v4.z;
  return clamp(vec3(dot(v4, r4) + dot(v2, r2), dot(v4, g4) + dot(v2, g2), dot(v4, b4) + dot(v2, b2)), 0.0, 1.0);
}

// Where v lies between lo and hi, in [0, 1]. Log: ln(v / lo') / ln(hi / lo') with lo' = max(lo, hi * 1e-6),
// so a range starting at 0 spans six decades below its top.
float heatmapT(float v, float lo, float hi, bool logScale) {
  if (logScale) {
    float l0 = max(lo, hi * 1e-6);
    if (!(hi > l0) || !(l0 > 0.0)) return 0.5;
    return clamp(log(max(v, l0) / l0) / log(hi / l0), 0.0, 1.0);
  }
  return hi > lo ? clamp((v - lo) / (hi - lo), 0.0, 1.0) : 0.5;
}

// Inverse of keys.glsl's interleaveBits: component k's bits back from the key (dropped levels read 0).
void deinterleaveBits(uint key, uint w[6], uint n, uint maxBits, out uint c[6]) {
  uint total = 0u;
  for (uint k = 0u; k < n; ++k) total += w[k];
  uint drop = total > maxBits ? total - maxBits : 0u;
  for (uint k = 0u; k < 6u; ++k) c[k] = 0u;
  uint pos = 0u;
  for (uint level = 0u; level < 32u; ++level) {
    bool any = false;
    for (uint k = 0u; k < n; ++k) {
      if (level >= w[k]) continue;
      any = true;
      if (pos >= drop) c[k] |= ((key >> (pos - drop)) & 1u) << level;
      ++pos;
    }
    if (!any) break;
  }
}

// The cell a live key encodes, and how many cells its space has per axis: the grid cell of the (estimated)
// end point for point keys, the end cell of two-point keys, the origin cell of origin-direction keys, the
// octahedral direction cell (u, v, 0) of direction keys; dead-last keys encode none (cell 0 of 1).
uvec3 keyCell(uint strategy, GpuKeyGrid g, uint key, out uvec3 cells) {
  uint c[6];
  cells = g.cells;
  if (strategy == RL_KEY_DIRECTION) {
    uint bitsU = (g.gridBits + 1u) / 2u, bitsV = g.gridBits / 2u;
    uint w[6] = uint[6](bitsU, bitsV, 0u, 0u, 0u, 0u);
    deinterleaveBits(key, w, 2u, 32u, c);
    cells = uvec3(1u << bitsU, 1u << bitsV, 1u);
    return uvec3(c[0], c[1], 0u);
  }
  if (strategy == RL_KEY_ORIGIN_DIRECTION) {
    uint m = g.maxAxisBits;
    uint w[6] = uint[6](g.bits.x, g.bits.y, g.bits.z, m, m, 0u);
    deinterleaveBits(key, w, 5u, RL_KEY_MAX_SPATIAL_BITS, c);
    return uvec3(c[0], c[1], c[2]);
  }
  if (strategy == RL_KEY_TWO_POINT) {
    uint w[6] = uint[6](g.bits.x, g.bits.y, g.bits.z, g.bits.x, g.bits.y, g.bits.z);
    deinterleaveBits(key, w, 6u, RL_KEY_TWO_POINT_BITS, c);
    return uvec3(c[3], c[4], c[5]);
  }
  if (strategy == RL_KEY_DEAD_LAST || strategy == RL_KEY_NONE) {
    cells = uvec3(1u);
    return uvec3(0u);
  }
  uint w[6] = uint[6](g.bits.x, g.bits.y, g.bits.z, 0u, 0u, 0u);
  deinterleaveBits(key, w, 3u, 32u, c);
  return uvec3(c[0], c[1], c[2]);
}

// A position colour: each axis of the cell's centre, as a fraction of the space, drives one channel.
vec3 cellColour(uvec3 cell, uvec3 cells) {
  vec3 f = (vec3(min(cell, cells - 1u)) + 0.5) / vec3(max(cells, uvec3(1u)));
  return 0.15 + 0.8 * f;
}

// cellColour over the cells [lo, hi] the frame's keys span (per axis), so the view's own part of the grid
// gets the whole colour range.
vec3 stretchedCellColour(uvec3 cell, uvec3 lo, uvec3 hi) {
  uvec3 l = min(lo, cell), h = max(hi, cell);
  return cellColour(cell - l, h - l + 1u);
}

// Equal keys share a colour; nothing else can be read from it.
vec3 hashColour(uint key) {
  uint h = pcgHash(key);
  return 0.25 + 0.75 * vec3(h & 255u, (h >> 8) & 255u, (h >> 16) & 255u) / 255.0;
}

// The colours of the sentinels and of cell-hit.
vec3 noPathColour() { return vec3(0.12); }
vec3 noValueColour() { return vec3(0.85, 0.85, 0.85); }
vec3 cellHitColour(bool hit) { return hit ? vec3(0.2, 0.8, 0.3) : vec3(0.85, 0.2, 0.2); }

uint packColour(vec3 c) {
  uvec3 b = uvec3(clamp(c, 0.0, 1.0) * 255.0 + 0.5);
  return b.r | (b.g << 8) | (b.b << 16) | (255u << 24);
}

uint packCell(uvec3 c) { return c.x | (c.y << RL_HEAT_CELL_BITS) | (c.z << (2u * RL_HEAT_CELL_BITS)); }

#endif
