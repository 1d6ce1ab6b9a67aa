#version 460
// The BVH traversal on its own: for each given ray the closest hit (traceClosest) and/or the shadow-ray
// answer (occluded) of the same functions the trace stage, the megakernel and next-event estimation call,
// so the tests check exactly what renders use (tests/gpu/bvh/test_embree_hits.cpp) and `raylab tracebench`
// times each kind of ray alone (app/tracebench).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#include "spec_ids.h"
#include "hit_query_types.h"
#include "bvh_traverse.glsl"
#include "dispatch_index.glsl"

layout(local_size_x_id = RL_SPEC_GROUP_SIZE) in;
layout(push_constant, scalar) uniform Push { HitQueryPush pc; };
layout(constant_id = RL_SPEC_HIT_QUERIES) const uint kQueries = RL_HIT_QUERY_CLOSEST | RL_HIT_QUERY_OCCLUDED;

void main() {
  uint i = flatInvocationIndex();
  if (i >= pc.count) return;
  GpuScene scene = GpuSceneBuf(pc.scene).s;
  vec3 origin = Vec4Buf(pc.origins).v[i].xyz;
  vec4 dir = Vec4Buf(pc.directions).v[i];
  uvec4 result = uvec4(floatBitsToUint(-1.0), 0xFFFFFFFFu, 0u, 0u);
  if ((kQueries & RL_HIT_QUERY_CLOSEST) != 0u) {
    HitRecord hit = traceClosest(scene, origin, dir.xyz, dir.w);
    uint triangle = hit.t > 0.0 ? scene.triangles.v[hit.triangle].sourceIndex : 0xFFFFFFFFu;
    result.xyw = uvec3(floatBitsToUint(hit.t), triangle, hit.steps);
  }
  if ((kQueries & RL_HIT_QUERY_OCCLUDED) != 0u) {
    // occluded()'s traversal, keeping its steps where it is the only query.
    HitRecord any = traverseSceneBvh(scene, origin, dir.xyz, dir.w, true);
    result.z = any.t > 0.0 ? 1u : 0u;
    if (kQueries == RL_HIT_QUERY_OCCLUDED) result.w = any.steps;
  }
  UVec4Buf(pc.results).v[i] = result;
}
