#version 460
// Baseline: every bounce of a path in one thread and one dispatch (the study's "ground truth"). The same
// functions as the wavefront stages, so both estimate the same integral with the same random streams.
// Reordering a work group's paths through shared memory between bounces (by the direction cell of the next ray)
// renders the same image and gives warps of more alike rays, but a group then waits at every bounce for its
// slowest warp (the likely cost): on an H100 frames took 1.04-1.12x as long with groups of 64 and 1.23-2.38x with 256-512
// (docs/results/group-sort-megakernel, whose group-sort.patch holds it).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#include "shared_types.h"
#include "simt_counting.glsl"
#include "path_shading.glsl"
#include "path_stage.glsl"
#include "dispatch_index.glsl"
#include "camera_order.h"

void main() {
  GpuFrame f = FrameBuf(pc.frame).f;
  gCounters = f.counters;
  gCounterBase = 0u;  // every bounce counts in bounce 0's slots
  const uint slot = flatInvocationIndex();
  if (slot >= f.pathCount) {
    countRays(0u);
    return;
  }
  const uint id = cameraPathOfSlot(slot, f.width, f.height, f.sppPerFrame);  // generate's order
  uint rng = rngSeed(id, f.frameIndex, 0u, f.seed, RL_RNG_CAMERA);
  PathVars p = cameraPath(f.camera, id / f.sppPerFrame, f.width, f.height, rng);
  uint steps = 0u, rays = 0u;
  vec3 radiance = vec3(0.0);
  for (uint b = 0u; b < f.bounceCount && p.alive; ++b) {
    HitRecord hit = traceClosest(f.scene, p.origin, p.direction, 1e30);
    steps += hit.steps;
    ++rays;
    rng = rngSeed(id, f.frameIndex, b, f.seed, RL_RNG_SHADE);
    p.radiance = vec3(0.0);
    shadePath(f.scene, p, hit, b, f.bounceCount, rng);
    radiance = addBounceRadiance(radiance, b, p.radiance);
  }
  f.hits.steps.v[slot] = steps;  // in dispatch order like the wavefront's (the heatmap maps slots to paths)
  f.results.v[id] = vec4(radiance, 1.0);
  countRays(rays);
}
