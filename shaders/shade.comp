#version 460
// Shades every live path at its hit (or miss), adds this bounce's radiance to results[pathId] and writes
// its next ray in place (or marks it finished). Results are indexed by path id, not by thread, so no pass is needed to
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
  if (!pathAlive(s, i)) return;  // one 16-byte load; loadPath reads the same element again
  uint id;
  PathVars p = loadPath(s, i, id);
  HitRecord hit = loadHit(f.hits, i);
  uint rng = rngSeed(id, f.frameIndex, pc.bounce, f.seed, RL_RNG_SHADE);
  shadePath(f.scene, p, hit, pc.bounce, f.bounceCount, rng);
  pathAddRadiance(f.results, id, pc.bounce, p.radiance);
  storePath(s, i, p, id);
}
