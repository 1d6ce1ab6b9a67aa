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
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#include "key_types.h"
#include "rng.glsl"
#include "keys.glsl"

layout(local_size_x_id = 0) in;
layout(constant_id = 1) const uint kStrategy = RL_KEY_AVERAGE;
layout(push_constant, scalar) uniform Push { KeyLearnPush pc; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= pc.count) return;
  FrameBuf frame = FrameBuf(pc.frame);
  GpuPathState state = frame.f.state[pc.stateSet];
  if (state.alive.v[i] == 0u) return;
  float t = frame.f.hits.t.v[i];
  vec3 dir = state.direction.v[i].xyz;
  if (!(t > 0.0 && t < 1e30) || !validDirection(dir)) return;
  GpuKeyParams params = KeyParamsBuf(pc.params).p;
  GpuLengthCache cache = params.cache;
  int e = cacheEntry(cache, params.grid, cellOf(params.grid, state.origin.v[i].xyz), dir);
  if (e < 0) return;
  GpuCacheEntry entry = cache.entries.v[e];
  float x = clampLength(t, cache.lengthMax);
  if (kStrategy == RL_KEY_GAUSSIAN && entry.count >= RL_GAUSS_MIN_SAMPLES &&
      abs(x - entry.mean) > cache.gaussOutlier * max(entry.sigma, cache.sigmaFloor)) {
    atomicAdd(cache.touched.v[1], 1u);
    return;
  }

  // Quantize relative to the shift key_merge.comp will use: |x - shift| <= lengthMax, so |q| <= 2^P.
  float shift = entry.count > 0u ? entry.mean : clampLength(params.fixedLength, cache.lengthMax);
  float qMax = cache.lengthMax * cache.invUnit;
  int q = int(clamp(round((x - shift) * cache.invUnit), -qMax, qMax));

  if (atomicAdd(cache.batches.v[e].count, 1u) == 0u) {
    uint slot = atomicAdd(cache.touched.v[0], 1u);
    cache.touched.v[2u + slot] = uint(e);
  }
  uint lo = uint(q);
  uint hi = q < 0 ? 0xFFFFFFFFu : 0u;  // sign extension to 64 bits
  uint old = atomicAdd(cache.batches.v[e].sumLo, lo);
  if (old + lo < old) hi += 1u;        // carry out of the low word
  if (hi != 0u) atomicAdd(cache.batches.v[e].sumHi, hi);
  uint64_t q2 = uint64_t(int64_t(q) * int64_t(q));
  lo = uint(q2);
  hi = uint(q2 >> 32);
  old = atomicAdd(cache.batches.v[e].sqLo, lo);
  if (old + lo < old) hi += 1u;
  if (hi != 0u) atomicAdd(cache.batches.v[e].sqHi, hi);
}
