#version 460
// Learning, part 1: after the trace of bounce b >= 1, each live path that hit something adds its actual
// hit distance to the batch of its ray's cache entry (origin cell, direction octant). Misses are skipped:
// they have no length, and a made-up one (e.g. the distance to the grid's boundary) would bias cells that
// see both sky and geometry; missed paths end anyway, so their keys never use the estimate.
//
// Race-free and deterministic: lengths are quantized to fixed point relative to the entry's current mean
// (which no thread changes during this pass) and summed with 32-bit integer atomics, 64-bit sums as two
// words with a software carry (64-bit atomics are optional in Vulkan). Integer sums do not depend on the
// order threads add in. key_merge.comp then folds each touched batch into its entry.
// Lanes that share an entry (the usual case once rays are sorted) first sum their samples across the
// subgroup and one lane adds the sums: far fewer atomics on hot entries, and the same integer totals.
// Sampled learning (Settings::learnEvery = k > 1): only every k-th slot learns, the phase moving with frame
// and bounce. The rays are in sort order here (learning follows sorted bounces only), so the sample is
// stratified along the keys: every region keeps learning, from k times fewer rays. Slots past the live
// prefix hold finished paths and are not read.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_EXT_shader_subgroup_extended_types_int64 : require
#include "spec_ids.h"
#include "key_types.h"
#include "rng.glsl"
#include "keys.glsl"
#include "path_state.glsl"
#include "dispatch_index.glsl"
#include "atomic_add_64.glsl"

layout(local_size_x_id = RL_SPEC_GROUP_SIZE) in;
layout(constant_id = RL_SPEC_KEY_STRATEGY) const uint kStrategy = RL_KEY_AVERAGE;
layout(push_constant, scalar) uniform Push { KeyLearnPush pc; };

void main() {
  uint i = flatInvocationIndex();
  GpuKeyParams params = KeyParamsBuf(pc.params).p;
  GpuLengthCache cache = params.cache;
  int e = -1;
  int64_t q = 0l;
  bool outlier = false;
  FrameBuf frame = FrameBuf(pc.frame);
  bool sampled = (i + frame.f.frameIndex + pc.bounce) % pc.learnEvery == 0u;
  if (i < pc.count && sampled && i < frame.f.live.v[RL_LIVE_COUNT]) {
    GpuPathState state = frame.f.state[pc.stateSet];
    float t = frame.f.hits.t.v[i];
    vec3 origin, dir;
    bool alive = pathRay(state, i, origin, dir);
    if (alive && t > 0.0 && t < 1e30 && validDirection(dir)) {
      e = cacheEntry(cache, params.grid, cellOf(params.grid, origin), dir);
      if (e >= 0) {
        GpuCacheEntry entry = cache.entries.v[e];
        float x = clampLength(t, cache.lengthMax);
        if (kStrategy == RL_KEY_GAUSSIAN && entry.count >= RL_GAUSS_MIN_SAMPLES &&
            abs(x - entry.mean) > cache.gaussOutlier * max(entry.sigma, cache.sigmaFloor)) {
          outlier = true;
          e = -1;
        } else {
          // Quantize relative to the shift key_merge.comp will use: |x - shift| <= lengthMax, so |q| <= 2^P.
          float shift = entry.count > 0u ? entry.mean : clampLength(params.fixedLength, cache.lengthMax);
          float qMax = cache.lengthMax * cache.invUnit;
          q = int64_t(int(clamp(round((x - shift) * cache.invUnit), -qMax, qMax)));
        }
      }
    }
  }
  uint outliers = subgroupAdd(outlier ? 1u : 0u);
  if (subgroupElect() && outliers > 0u) atomicAdd(cache.touched.v[1], outliers);

  // Peel one entry per iteration: the first pending lane's entry, summed over every lane that has it.
  bool pending = e >= 0;
  while (pending) {
    int leader = subgroupBroadcastFirst(e);
    bool mine = e == leader;
    uint n = subgroupAdd(mine ? 1u : 0u);
    int64_t sum = subgroupAdd(mine ? q : 0l);
    int64_t sumSq = subgroupAdd(mine ? q * q : 0l);
    if (subgroupElect()) {
      if (atomicAdd(cache.batches.v[leader].count, n) == 0u) {
        uint slot = atomicAdd(cache.touched.v[0], 1u);
        cache.touched.v[2u + slot] = uint(leader);
      }
      ATOMIC_ADD_64(cache.batches.v[leader].sumLo, cache.batches.v[leader].sumHi, uint64_t(sum));
      ATOMIC_ADD_64(cache.batches.v[leader].sqLo, cache.batches.v[leader].sqHi, uint64_t(sumSq));
    }
    if (mine) pending = false;
  }
}
