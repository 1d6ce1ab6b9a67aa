#version 460
// Shades every live path at its hit (or miss), adds this bounce's radiance to results[pathId] and writes
// its next ray in place (or marks it finished). Results are indexed by path id, not by thread, so no pass is needed to
// restore the order that sorting changed, and the accumulate pass sums them in a fixed pixel order.
// With spec constant 1 set to a key strategy (Settings::fusion keys), shade also makes the sort key of the
// ray it writes, as keys.comp would from the stored ray (the same bits: computeKey of the same floats), so
// the separate keys pass and its 32-byte read of every ray go away.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#include "shared_types.h"
#include "key_types.h"
#include "path_shading.glsl"
#include "path_stage.glsl"
#include "keys.glsl"

layout(constant_id = 1) const uint kKeyStrategy = RL_KEY_NONE;

// keys.comp's output for slot i: the key and the slot as the sort's payload; the predicted length.
void storeKey(GpuFrame f, uint i, PathVars p, uint id, out float len) {
  KeyPath path;
  path.origin = p.origin;
  path.direction = p.direction;
  path.pathId = id;
  path.oracleT = -1.0;
  KeyEnv env;
  env.frameIndex = f.frameIndex;
  env.bounce = pc.bounce;
  env.seed = f.seed;
  f.sortKeys.v[i] = computeKey(kKeyStrategy, KeyParamsBuf(f.keyParams).p, env, path, p.alive ? 1u : 0u, len);
  f.sortValues.v[i] = i;
}

void main() {
  GpuFrame f = FrameBuf(pc.frame).f;
  uint i = gl_GlobalInvocationID.x;
  if (i >= f.live.v[RL_LIVE_COUNT]) return;
  GpuPathState s = f.state[pc.stateSet];
  if (!pathAlive(s, i)) {  // one 16-byte load; loadPath reads the same element again
    if (kKeyStrategy != RL_KEY_NONE) {
      f.sortKeys.v[i] = RL_DEAD_KEY;
      f.sortValues.v[i] = i;
    }
    return;
  }
  uint id;
  PathVars p = loadPath(s, i, id);
  HitRecord hit = loadHit(f.hits, i);
  uint rng = rngSeed(id, f.frameIndex, pc.bounce, f.seed, RL_RNG_SHADE);
  shadePath(f.scene, p, hit, pc.bounce, f.bounceCount, rng);
  pathAddRadiance(f.results, id, pc.bounce, p.radiance);
  float len = -1.0;
  if (kKeyStrategy != RL_KEY_NONE) storeKey(f, i, p, id, len);
  storePath(s, i, p, id, len);
}
