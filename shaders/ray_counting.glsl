// The per-bounce ray count (GpuFrame::counters' RL_COUNTER_RAYS), shared by the stages that trace: trace.comp
// and the megakernel (through simt_counting.glsl) and shade.comp when it traces first (Settings::traceShade).
#ifndef RAYLAB_RAY_COUNTING_GLSL
#define RAYLAB_RAY_COUNTING_GLSL

#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_arithmetic : require

// The counters (GpuFrame::counters) and the first slot of this bounce's RL_COUNTER_STRIDE words; set both
// at the start of main().
UintBuf gCounters;
uint gCounterBase;

// Adds each lane's ray count to the RL_COUNTER_RAYS slot with one atomic per subgroup.
void countRays(uint rays) {
  uint total = subgroupAdd(rays);
  if (subgroupElect() && total > 0u) atomicAdd(gCounters.v[gCounterBase + RL_COUNTER_RAYS], total);
}

#endif
