#version 460
// Shades every live path at its hit (or miss), adds this bounce's radiance to results[pathId] and writes
// its next ray in place (or marks it finished). Results are indexed by path id, not by thread, so no pass is needed to
// restore the order that sorting changed, and the accumulate pass sums them in a fixed pixel order.
// With spec constant 1 set to a key strategy (Settings::fusion keys), shade also makes the sort key of the
// ray it writes, as keys.comp would from the stored ray (the same bits: computeKey of the same floats), so
// the separate keys pass and its 32-byte read of every ray go away.
// With spec constant 2 (Settings::compaction shade) the paths that stay alive are compacted instead of
// written in place: each subgroup counts its survivors (a ballot's prefix sum), takes that many slots of
// the other state set with one atomic, and writes its paths there in lane order; finished paths are not
// written at all. The next trace then visits only live paths, packed into full warps. Which warp gets which
// slots depends on timing, but a path's id, never its slot, picks its pixel, random numbers and results
// entry, so the image is the same bit for bit. When the frame sorts, every slot it visits also gets the dead
// key: the keys pass then writes keys for the new, shorter live prefix only, and the sort and reorder rely
// on dead keys behind it (the last sort's would be stale).
// With spec constant 3 (Settings::traceShade fused) shade also does the bounce's trace: it traces the ray it
// loaded (trace.comp's traversal of the same floats, so the same hit) and counts it, and no hit record is
// written or read. It writes no traversal steps (nothing reads them where the host fuses).
// With spec constant 8 as well (Settings::loopsBounces) each thread goes on to the path's end: trace, shade
// and the radiance of every bounce from this one, in registers, as the megakernel does (the same functions in
// the same order, the radiance summed as pathAddRadiance would: the same image bit for bit). The host
// dispatches it after the frame's last sort, where nothing reads the state, hits or keys between bounces.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#include "spec_ids.h"
#include "shared_types.h"
#include "key_types.h"
#include "path_shading.glsl"
#include "path_stage.glsl"
#include "keys.glsl"
#include "ray_counting.glsl"
#include "dispatch_index.glsl"

layout(constant_id = RL_SPEC_KEY_STRATEGY) const uint kKeyStrategy = RL_KEY_NONE;
layout(constant_id = RL_SPEC_COMPACT) const bool kCompact = false;
layout(constant_id = RL_SPEC_FUSES_TRACE_SHADE) const bool kFusesTraceShade = false;
layout(constant_id = RL_SPEC_LOOPS_BOUNCES) const bool kLoopsBounces = false;

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

// Compaction: path `id` (alive or not) of this lane joins the live prefix of the other state set, in the
// block of GpuFrame::live this bounce appends to (RL_LIVE_APPEND). Called by every lane that shaded a path.
void appendPath(GpuFrame f, PathVars p, uint id) {
  uvec4 survivors = subgroupBallot(p.alive);
  uint n = subgroupBallotBitCount(survivors);
  if (n == 0u) return;
  uint block = RL_LIVE_APPEND + pc.bounce * RL_LIVE_WORDS;
  uint base = 0u;
  if (subgroupElect()) {
    base = atomicAdd(f.live.v[block + RL_LIVE_COUNT], n);
    // The last subgroup to append does not know it is last: every one raises the dispatch size to cover its
    // own slots, so the largest (the final one) wins. Both grid sides grow with the group count, so the
    // maxima of each are the final count's grid.
    uvec3 groups = dispatchGridFor(base + n, RL_PATH_GROUP_SIZE, f.dispatchRowGroups);
    atomicMax(f.live.v[block + RL_LIVE_DISPATCH + 0u], groups.x);
    atomicMax(f.live.v[block + RL_LIVE_DISPATCH + 1u], groups.y);
  }
  base = subgroupBroadcastFirst(base);
  if (p.alive) storePath(f.state[1u - pc.stateSet], base + subgroupBallotExclusiveBitCount(survivors), p, id);
}

// The bounce loop (kLoopsBounces): path `id` from bounce pc.bounce to its end. Rays are counted per bounce as
// trace.comp counts them.
void finishPath(GpuFrame f, PathVars p, uint id) {
  vec3 radiance = pc.bounce == 0u ? vec3(0.0) : f.results.v[id].xyz;
  uint b = pc.bounce;
  for (; b < f.bounceCount && p.alive; ++b) {
    HitRecord hit = traceClosest(f.scene, p.origin, p.direction, 1e30);
    uint rng = rngSeed(id, f.frameIndex, b, f.seed, RL_RNG_SHADE);
    p.radiance = vec3(0.0);
    shadePath(f.scene, p, hit, b, f.bounceCount, rng);
    radiance = addBounceRadiance(radiance, b, p.radiance);
  }
  f.results.v[id] = vec4(radiance, 1.0);
  // Bounce c's rays: the lanes whose loop traced it, counted after the loop, where the subgroup has reconverged.
  gCounters = f.counters;
  for (uint c = pc.bounce; c < f.bounceCount; ++c) {
    gCounterBase = c * RL_COUNTER_STRIDE;
    countRays(c < b ? 1u : 0u);
  }
}

void main() {
  GpuFrame f = FrameBuf(pc.frame).f;
  uint i = flatInvocationIndex();
  if (i >= f.live.v[RL_LIVE_COUNT]) return;
  if (kCompact && uint64_t(f.keyParams) != 0ul) {  // key parameters are set only when the frame sorts
    f.sortKeys.v[i] = RL_DEAD_KEY;
    f.sortValues.v[i] = i;
  }
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
  if (kLoopsBounces) {
    finishPath(f, p, id);
    return;
  }
  HitRecord hit;
  if (kFusesTraceShade) {
    hit = traceClosest(f.scene, p.origin, p.direction, 1e30);
    gCounters = f.counters;  // as trace.comp counts: one ray for each live lane
    gCounterBase = pc.bounce * RL_COUNTER_STRIDE;
    countRays(1u);
  } else {
    hit = loadHit(f.hits, i);
  }
  // Slot i may lie behind the next live prefix, which the next trace does not visit: no stale steps there
  // for the warp statistics (as markSlotEmpty after a sort).
  if (kCompact) f.hits.steps.v[i] = 0u;
  uint rng = rngSeed(id, f.frameIndex, pc.bounce, f.seed, RL_RNG_SHADE);
  shadePath(f.scene, p, hit, pc.bounce, f.bounceCount, rng);
  pathAddRadiance(f.results, id, pc.bounce, p.radiance);
  float len = -1.0;
  if (kKeyStrategy != RL_KEY_NONE) storeKey(f, i, p, id, len);
  if (kCompact)
    appendPath(f, p, id);
  else
    storePath(s, i, p, id, len);
}
