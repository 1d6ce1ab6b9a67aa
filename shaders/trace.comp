#version 460
// Closest-hit traversal of every live path's ray; records the hit and the loop iteration count.
// With the counting variant (spec constant 1), each traversal iteration also counts the subgroup's
// active lanes with a ballot: the device's own SIMT efficiency. The plain variant compiles that away.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#include "shared_types.h"

layout(constant_id = 1) const bool kCountSimt = false;
UintBuf gCounters;
#define RL_TRAVERSAL_STEP()                                         \
  if (kCountSimt) {                                                 \
    uint activeLanes = subgroupBallotBitCount(subgroupBallot(true));     \
    if (subgroupElect()) {                                          \
      atomicAdd(gCounters.v[1], activeLanes);                            \
      atomicAdd(gCounters.v[2], 1u);                                \
    }                                                               \
  }
#include "path_shading.glsl"
#include "path_stage.glsl"

void main() {
  GpuFrame f = FrameBuf(pc.frame).f;
  gCounters = f.counters;
  uint i = gl_GlobalInvocationID.x;
  bool live = i < f.pathCount && f.state[pc.stateSet].alive.v[i] != 0u;
  uint rays = subgroupAdd(live ? 1u : 0u);
  if (subgroupElect() && rays > 0u) atomicAdd(f.counters.v[0], rays);
  if (i >= f.pathCount) return;
  HitRecord hit;
  hit.t = -1.0;
  hit.triangle = 0u;
  hit.bary = vec2(0.0);
  hit.steps = 0u;
  if (live) {
    GpuPathState s = f.state[pc.stateSet];
    hit = traceClosest(f.scene, s.origin.v[i].xyz, s.direction.v[i].xyz, 1e30);
  }
  f.hits.t.v[i] = hit.t;
  f.hits.triangle.v[i] = hit.triangle;
  f.hits.barycentric.v[i] = hit.bary;
  f.hits.steps.v[i] = hit.steps;
}
