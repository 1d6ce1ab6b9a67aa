#version 460
// Accumulated radiance -> display RGBA8: average the samples, apply exposure, ACES-fitted tone curve, sRGB.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#include "spec_ids.h"
#include "shared_types.h"
#include "color.glsl"
#include "dispatch_index.glsl"

layout(local_size_x_id = RL_SPEC_GROUP_SIZE) in;
layout(push_constant, scalar) uniform Push { PathStagePush pc; };

void main() {
  GpuFrame f = FrameBuf(pc.frame).f;
  uint pixel = flatInvocationIndex();
  if (pixel >= f.width * f.height) return;
  vec4 sum = f.accumulation.v[pixel];
  vec3 rgb = sum.w > 0.0 ? sum.xyz / sum.w : vec3(0.0);
  f.image.v[pixel] = packDisplayColor(rgb * f.exposure);
}
