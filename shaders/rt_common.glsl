// What the ray-tracing stages of the rt tracer share: the payload of a closest-hit trace (filled by
// rt_closest_hit.rchit or rt_miss.rmiss), the payload locations and the miss-shader indices of the
// shader binding table (renderer/vk/rt_pipeline.cpp builds the table in this order).
#ifndef RAYLAB_RT_COMMON_GLSL
#define RAYLAB_RT_COMMON_GLSL

#define RL_RT_PAYLOAD_HIT 0     // RtHitPayload
#define RL_RT_PAYLOAD_SHADOW 1  // uint: 1 occluded, the shadow miss shader writes 0
#define RL_RT_MISS_PRIMARY 0    // rt_miss.rmiss
#define RL_RT_MISS_SHADOW 1     // rt_shadow_miss.rmiss

// The hit in the layout of HitRecord (bvh_traverse.glsl): the BLAS holds the triangles in BVH order, so
// gl_PrimitiveID is the BVH-order triangle index the shade stage reads, and the hit attributes are the
// barycentrics of v1 and v2, as Moeller-Trumbore's (u, v).
struct RtHitPayload {
  float t;  // negative: no hit
  uint triangle;
  vec2 bary;
};

#endif
