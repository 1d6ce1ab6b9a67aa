#version 460
// Closest-hit traversal of every live path's ray; records the hit and the loop iteration count.
// The counting variant (simt_counting.glsl) also counts active lanes per traversal iteration.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#include "shared_types.h"
#include "simt_counting.glsl"
#include "path_shading.glsl"
#include "path_stage.glsl"

void main() {
  GpuFrame f = FrameBuf(pc.frame).f;
  gCounters = f.counters;
  gCounterBase = pc.bounce * RL_COUNTER_STRIDE;
  uint i = gl_GlobalInvocationID.x;
  uint count = f.live.v[RL_LIVE_COUNT];
  GpuPathState s = f.state[pc.stateSet];
  vec3 origin, direction;
  bool live = i < count && pathRay(s, i, origin, direction);
  countRays(live ? 1u : 0u);
  if (i >= count) return;
  HitRecord hit;
  hit.t = -1.0;
  hit.triangle = 0u;
  hit.bary = vec2(0.0);
  hit.steps = 0u;
  if (live) hit = traceClosest(f.scene, origin, direction, 1e30);
  storeHit(f.hits, i, hit);
}
