#version 460
// Adds this frame's samples of each pixel to its running sum, in sample order: the same result whatever
// order the paths finished in. A non-finite sum (a numerical accident) counts as black rather than
// poisoning the pixel forever.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#include "shared_types.h"
#include "path_stage.glsl"
#include "dispatch_index.glsl"

void main() {
  GpuFrame f = FrameBuf(pc.frame).f;
  uint pixel = flatInvocationIndex();
  if (pixel >= f.width * f.height) return;
  vec4 sum = f.accumulation.v[pixel];
  for (uint s = 0u; s < f.sppPerFrame; ++s) sum += finishedRadiance(f.results.v[pixel * f.sppPerFrame + s].xyz);
  f.accumulation.v[pixel] = sum;
}
