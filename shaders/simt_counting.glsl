// SIMT counting for the traversal loop, shared by the trace stage and the megakernel: with spec constant 1
// set, every traversal iteration counts the subgroup's active lanes with a ballot (the device's own SIMT
// efficiency); the plain variant compiles it away. Include before path_shading.glsl.
#ifndef RAYLAB_SIMT_COUNTING_GLSL
#define RAYLAB_SIMT_COUNTING_GLSL

#include "spec_ids.h"
#include "ray_counting.glsl"

layout(constant_id = RL_SPEC_COUNT_SIMT) const bool kCountSimt = false;
#define RL_TRAVERSAL_STEP()                                                               \
  if (kCountSimt) {                                                                       \
    uint activeLanes = subgroupBallotBitCount(subgroupBallot(true));                      \
    if (subgroupElect()) {                                                                \
      atomicAdd(gCounters.v[gCounterBase + RL_COUNTER_SIMT_ACTIVE], activeLanes);         \
      atomicAdd(gCounters.v[gCounterBase + RL_COUNTER_SIMT_SLOTS], 1u);                   \
    }                                                                                     \
  }

#endif
