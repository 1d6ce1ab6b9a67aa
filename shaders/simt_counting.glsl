// SIMT counting for the traversal loop, shared by the trace stage and the megakernel: with spec constant 1
// set, every traversal iteration counts the subgroup's active lanes with a ballot (the device's own SIMT
// efficiency); the plain variant compiles it away. Include before path_shading.glsl.
#ifndef RAYLAB_SIMT_COUNTING_GLSL
#define RAYLAB_SIMT_COUNTING_GLSL

#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_arithmetic : require

layout(constant_id = 1) const bool kCountSimt = false;
UintBuf gCounters;
#define RL_TRAVERSAL_STEP()                                          \
  if (kCountSimt) {                                                  \
    uint activeLanes = subgroupBallotBitCount(subgroupBallot(true)); \
    if (subgroupElect()) {                                           \
      atomicAdd(gCounters.v[1], activeLanes);                        \
      atomicAdd(gCounters.v[2], 1u);                                 \
    }                                                                \
  }

// Adds each lane's ray count to counters[0] with one atomic per subgroup.
void countRays(uint rays) {
  uint total = subgroupAdd(rays);
  if (subgroupElect() && total > 0u) atomicAdd(gCounters.v[0], total);
}

#endif
