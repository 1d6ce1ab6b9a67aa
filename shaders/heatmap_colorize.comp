#version 460
// Heatmap values to display colours: sort keys hashed (equal keys share a colour), cell hits green/red,
// everything else through a perceptual ramp over the frame's value range; empty pixels dark grey.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#include "heatmap_types.h"
#include "rng.glsl"

layout(local_size_x_id = 0) in;
layout(push_constant, scalar) uniform Push { HeatmapPush pc; };

// Polynomial fit of the Turbo colour map (Mikhailov 2019).
vec3 turbo(float x) {
  const vec4 r4 = vec4(0.13572138, 4.61539260, -42.66032258, 132.13108234);
  const vec4 g4 = vec4(0.09140261, 2.19418839, 4.84296658, -14.18503333);
  const vec4 b4 = vec4(0.10667330, 12.64194608, -60.58204836, 110.36276771);
  const vec2 r2 = vec2(-152.94239396, 59.28637943);
  const vec2 g2 = vec2(4.27729857, 2.82956604);
  const vec2 b2 = vec2(-89.90310912, 27.34824973);
  x = clamp(x, 0.0, 1.0);
  vec4 v4 = vec4(1.0, x, x * x, x * x * x);
  vec2 v2 = v4.zw * v4.z;
  return vec3(dot(v4, r4) + dot(v2, r2), dot(v4, g4) + dot(v2, g2), dot(v4, b4) + dot(v2, b2));
}

uint pack(vec3 c) {
  uvec3 b = uvec3(clamp(c, 0.0, 1.0) * 255.0 + 0.5);
  return b.r | (b.g << 8) | (b.b << 16) | (255u << 24);
}

void main() {
  GpuFrame f = FrameBuf(pc.frame).f;
  uint pixel = gl_GlobalInvocationID.x;
  if (pixel >= f.width * f.height) return;
  uint bits = pc.heat.v[pixel];
  vec3 c;
  if (bits == RL_HEAT_EMPTY) {
    c = vec3(0.12);
  } else if (pc.view == RL_HEAT_SORT_KEY) {
    uint h = pcgHash(bits);
    c = 0.25 + 0.75 * vec3(h & 255u, (h >> 8) & 255u, (h >> 16) & 255u) / 255.0;
  } else if (pc.view == RL_HEAT_CELL_HIT) {
    c = uintBitsToFloat(bits) > 0.5 ? vec3(0.2, 0.8, 0.3) : vec3(0.85, 0.2, 0.2);
  } else {
    float lo = uintBitsToFloat(pc.range.v[0]), hi = uintBitsToFloat(pc.range.v[1]);
    float v = uintBitsToFloat(bits);
    c = turbo(hi > lo ? (v - lo) / (hi - lo) : 0.5);
  }
  f.image.v[pixel] = pack(c);
}
