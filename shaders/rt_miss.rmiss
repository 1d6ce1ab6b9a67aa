#version 460
// Miss shader of closest-hit rays: no hit (negative distance), as the compute traversal reports it.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_ray_tracing : require
#include "rt_common.glsl"

layout(location = RL_RT_PAYLOAD_HIT) rayPayloadInEXT RtHitPayload gHit;

void main() {
  gHit.t = -1.0;
  gHit.triangle = 0u;
  gHit.bary = vec2(0.0);
}
