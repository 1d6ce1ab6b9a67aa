#version 460
// The BVH traversal on its own, for tests: for each given ray the closest hit (traceClosest) and the
// shadow-ray answer (occluded) of the same functions the trace stage, the megakernel and next-event
// estimation call, so the test checks exactly what renders use (tests/gpu/bvh/test_embree_hits.cpp).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#include "spec_ids.h"
#include "hit_query_types.h"
#include "bvh_traverse.glsl"
#include "dispatch_index.glsl"

layout(local_size_x_id = RL_SPEC_GROUP_SIZE) in;
layout(push_constant, scalar) uniform Push { HitQueryPush pc; };

void main() {
  uint i = flatInvocationIndex();
  if (i >= pc.count) return;
  GpuScene scene = GpuSceneBuf(pc.scene).s;
  vec3 origin = Vec4Buf(pc.origins).v[i].xyz;
  vec4 dir = Vec4Buf(pc.directions).v[i];
  HitRecord hit = traceClosest(scene, origin, dir.xyz, dir.w);
  uint triangle = hit.t > 0.0 ? scene.triangles.v[hit.triangle].sourceIndex : 0xFFFFFFFFu;
  uint blocked = occluded(scene, origin, dir.xyz, dir.w) ? 1u : 0u;
  UVec4Buf(pc.results).v[i] = uvec4(floatBitsToUint(hit.t), triangle, blocked, hit.steps);
}
