// SIMT counting for the traversal loop, shared by the trace stage and the megakernel: with spec constant 1
// set, every traversal iteration counts the subgroup's active lanes with a ballot (the device's own SIMT
// efficiency); the plain variant compiles it away. Include before path_shading.glsl.
#ifndef RAYLAB_SIMT_COUNTING_GLSL
#define RAYLAB_SIMT_COUNTING_GLSL

#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_arithmetic : require

layout(constant_id = 1) const bool kCountSimt = false;
// The counters (GpuFrame::counters) and the first slot of this bounce's RL_COUNTER_STRIDE words; set both
// at the start of main().
UintBuf gCounters;
uint gCounterBase;
#define RL_TRAVERSAL_STEP()                                                               \
  if (kCountSimt) {                                                                       \
    uint activeLanes = subgroupBallotBitCount(subgroupBallot(true));                      \
    if (subgroupElect()) {                                                                \
      atomicAdd(gCounters.v[gCounterBase + RL_COUNTER_SIMT_ACTIVE], activeLanes);         \
      atomicAdd(gCounters.v[gCounterBase + RL_COUNTER_SIMT_SLOTS], 1u);                   \
    }                                                                                     \
  }

// Adds each lane's ray count to the RL_COUNTER_RAYS slot with one atomic per subgroup.
void countRays(uint rays) {
  uint total = subgroupAdd(rays);
  if (subgroupElect() && total > 0u) atomicAdd(gCounters.v[gCounterBase + RL_COUNTER_RAYS], total);
}

#endif
