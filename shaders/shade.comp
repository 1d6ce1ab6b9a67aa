#version 460
// Shades every live path at its hit (or miss) and writes its next ray in place; a path that ends writes
// its radiance to results[pathId]. Results are indexed by path id, not by thread, so no pass is needed to
// restore the order that sorting changed, and the accumulate pass sums them in a fixed pixel order.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#include "shared_types.h"
#include "path_shading.glsl"
#include "path_stage.glsl"

void main() {
  GpuFrame f = FrameBuf(pc.frame).f;
  uint i = gl_GlobalInvocationID.x;
  if (i >= f.live.v[RL_LIVE_COUNT]) return;
  GpuPathState s = f.state[pc.stateSet];
  if (s.alive.v[i] == 0u) return;
  PathVars p = loadPath(s, i);
  uint id = s.pathId.v[i];
  HitRecord hit;
  hit.t = f.hits.t.v[i];
  hit.triangle = f.hits.triangle.v[i];
  hit.bary = f.hits.barycentric.v[i];
  hit.steps = 0u;
  uint rng = rngSeed(id, f.frameIndex, pc.bounce, f.seed, RL_RNG_SHADE);
  shadePath(f.scene, p, hit, pc.bounce, f.bounceCount, rng);
  storePath(s, i, p);
  if (!p.alive) f.results.v[id] = finishedRadiance(p);
}
