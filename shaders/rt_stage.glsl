// Preamble of the rt tracer's ray-generation shaders: the closest-hit trace and the visibility test
// through VK_KHR_ray_tracing_pipeline in place of our BVH traversal, then the shared integrator
// (path_shading.glsl) with RL_OCCLUDED bound to the visibility test. The including shader enables
// GL_EXT_ray_tracing and GL_EXT_buffer_reference/scalar_block_layout, and defines RL_RT_SUBGROUPS to 1 when
// the device runs subgroup operations in ray-generation shaders (0: one atomic per ray to count rays).
#ifndef RAYLAB_RT_STAGE_GLSL
#define RAYLAB_RT_STAGE_GLSL

#define RL_RAY_TRACING_STAGE 1
#include "shared_types.h"
#include "bvh_traverse.glsl"
#include "rt_common.glsl"

layout(location = RL_RT_PAYLOAD_HIT) rayPayloadEXT RtHitPayload gHitPayload;
layout(location = RL_RT_PAYLOAD_SHADOW) rayPayloadEXT uint gShadowed;

HitRecord rtTraceClosest(GpuScene scene, vec3 origin, vec3 dir, float tMax) {
  traceRayEXT(accelerationStructureEXT(scene.tlas), gl_RayFlagsOpaqueEXT, 0xFF, 0, 1, RL_RT_MISS_PRIMARY, origin,
              0.0, dir, tMax, RL_RT_PAYLOAD_HIT);
  HitRecord hit;
  hit.t = gHitPayload.t;
  hit.triangle = gHitPayload.triangle;
  hit.bary = gHitPayload.bary;
  hit.steps = 0u;  // the driver's traversal: no loop to count
  return hit;
}

// Shadow rays: the first hit ends the traversal and no closest-hit shader runs; only the miss clears it.
bool rtOccluded(GpuScene scene, vec3 origin, vec3 dir, float tMax) {
  gShadowed = 1u;
  traceRayEXT(accelerationStructureEXT(scene.tlas),
              gl_RayFlagsOpaqueEXT | gl_RayFlagsTerminateOnFirstHitEXT | gl_RayFlagsSkipClosestHitShaderEXT, 0xFF,
              0, 1, RL_RT_MISS_SHADOW, origin, 0.0, dir, tMax, RL_RT_PAYLOAD_SHADOW);
  return gShadowed != 0u;
}

#define RL_OCCLUDED rtOccluded
#include "path_shading.glsl"

// Adds `rays` to the RL_COUNTER_RAYS slot at `base`: one atomic per subgroup where ray-generation shaders
// have subgroup operations, else one per ray.
void rtCountRays(UintBuf counters, uint base, uint rays) {
#if RL_RT_SUBGROUPS
  uint total = subgroupAdd(rays);
  if (subgroupElect() && total > 0u) atomicAdd(counters.v[base + RL_COUNTER_RAYS], total);
#else
  if (rays > 0u) atomicAdd(counters.v[base + RL_COUNTER_RAYS], rays);
#endif
}

#endif
