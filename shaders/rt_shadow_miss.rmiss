#version 460
// Miss shader of shadow rays: nothing between the point and the light. Shadow rays are traced with
// terminate-on-first-hit and skip-closest-hit, so a hit runs no shader and leaves the payload at 1.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_ray_tracing : require
#include "rt_common.glsl"

layout(location = RL_RT_PAYLOAD_SHADOW) rayPayloadInEXT uint gShadowed;

void main() { gShadowed = 0u; }
