#version 460
// The one hit group of the rt tracer (opaque triangles, no any-hit shader): the hit, as the trace stage
// of the compute tracer records it.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_ray_tracing : require
#include "rt_common.glsl"

layout(location = RL_RT_PAYLOAD_HIT) rayPayloadInEXT RtHitPayload gHit;
hitAttributeEXT vec2 gBarycentrics;

void main() {
  gHit.t = gl_HitTEXT;
  gHit.triangle = gl_PrimitiveID;
  gHit.bary = gBarycentrics;
}
