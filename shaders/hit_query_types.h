// hit_query.comp's push constants, shared with its C++ caller (tests/gpu/bvh/test_embree_hits.cpp). Data only,
// scalar block layout; tests/cpu/test_shared_layout.cpp asserts the host size.
#ifndef RAYLAB_HIT_QUERY_TYPES_H
#define RAYLAB_HIT_QUERY_TYPES_H

#include "shared_types.h"

#ifndef __cplusplus
layout(buffer_reference, scalar) buffer GpuSceneBuf { GpuScene s; };
#endif

#ifdef __cplusplus
namespace raylab::gpu {
#endif

// One thread per ray: origins (xyz; w unused) and directions (xyz; w: tMax) in, one uvec4 per ray out:
// closest hit t (float bits, negative on a miss), its triangle's scene index (GpuTriangle::sourceIndex),
// whether anything lies before tMax (the shadow-ray query), the closest-hit traversal's steps (the shadow
// ray's where it is the only query; 0 unless the pipeline counts them, RL_SPEC_COUNTS_STEPS). The
// pipeline's RL_SPEC_HIT_QUERIES says which of the two traversals run (the tests ask both; `raylab
// tracebench` times each kind of ray alone, with only its traversal's code in the pipeline, as the trace
// stage and the public kernels have); a query not asked reads as a miss (t -1, triangle ~0, 0 steps) or as
// not blocked.
#define RL_HIT_QUERY_CLOSEST 1u
#define RL_HIT_QUERY_OCCLUDED 2u
struct HitQueryPush {
  RL_REF(GpuSceneBuf) scene;
  RL_REF(Vec4Buf) origins;
  RL_REF(Vec4Buf) directions;
  RL_REF(UVec4Buf) results;
  uint count;
  uint pad0;
};

#ifdef __cplusplus
}  // namespace raylab::gpu
#endif

#endif
