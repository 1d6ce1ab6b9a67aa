#version 460
// Learning, part 2: one thread per entry touched this bounce folds its batch into the entry and clears
// the batch. The batch's mean and M2 come from exact integer sums; average and gaussian combine them with
// the entry by Chan et al.'s parallel formula (all terms non-negative: no cancellation, M2 never < 0);
// ema moves the mean toward the batch mean by 1 - (1 - alpha)^n, as n single updates with the batch mean
// would. Gaussian cells whose variance exceeds gaussReset drop their past and keep only this batch (or
// nothing, when the batch alone is above it).
// Each bounce counts the entries it reset in GpuFrame::counters' RL_COUNTER_CACHE_RESETS slot, one atomic per
// subgroup: Gaussian resets and non-finite restarts together (an entry is counted once even if both apply),
// since either drops what the entry had learned; the latter only guards against NaN and infinity and should
// never fire.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#include "spec_ids.h"
#include "key_types.h"
#include "rng.glsl"
#include "keys.glsl"
#include "dispatch_index.glsl"

layout(local_size_x_id = RL_SPEC_GROUP_SIZE) in;
layout(constant_id = RL_SPEC_KEY_STRATEGY) const uint kStrategy = RL_KEY_AVERAGE;
layout(push_constant, scalar) uniform Push { KeyLearnPush pc; };

float varianceOf(float count, float m2) { return count >= 2.0 ? m2 / (count - 1.0) : 0.0; }

// Folds the batch of the i-th touched entry into it; true when the entry was reset.
bool mergeTouched(uint i) {
  GpuKeyParams params = KeyParamsBuf(pc.params).p;
  GpuLengthCache cache = params.cache;
  if (i >= cache.touched.v[0]) return false;
  uint e = cache.touched.v[2u + i];
  GpuCacheBatch b = cache.batches.v[e];
  cache.batches.v[e] = GpuCacheBatch(0u, 0u, 0u, 0u, 0u);
  if (b.count == 0u) return false;
  GpuCacheEntry c = cache.entries.v[e];

  // Batch statistics in quantized units. With sum = m n + r (integer division), the batch's M2 is
  // sq - m^2 n - 2 m r - r^2 / n: everything but the last, small term is exact in 64-bit integers.
  int64_t sum = int64_t(uint64_t(b.sumLo) | (uint64_t(b.sumHi) << 32));
  int64_t sq = int64_t(uint64_t(b.sqLo) | (uint64_t(b.sqHi) << 32));
  int64_t n = int64_t(b.count);
  int64_t m = sum / n;
  int64_t r = sum - m * n;
  int64_t a = sq - m * m * n - 2 * m * r;
  float nB = float(b.count);
  float m2B = max(float(a) - float(r) * (float(r) / nB), 0.0) * cache.unit * cache.unit;
  float delta = (float(sum) / nB) * cache.unit;  // batch mean minus the shift the samples were taken against
  float shift = c.count > 0u ? c.mean : clampLength(params.fixedLength, cache.lengthMax);
  float meanB = shift + delta;

  float count = nB;
  float mean = meanB;
  float m2 = m2B;
  if (c.count > 0u) {
    float nA = float(c.count);
    count = nA + nB;
    if (kStrategy == RL_KEY_EMA) {
      mean = c.mean + (1.0 - exp2(nB * log2(1.0 - cache.emaAlpha))) * delta;
      m2 = 0.0;
    } else {
      mean = c.mean + delta * (nB / count);
      m2 = c.m2 + m2B + delta * delta * (nA * (nB / count));
    }
  }
  if (count > float(RL_CACHE_COUNT_CAP)) {  // saturate; keep the variance
    m2 *= float(RL_CACHE_COUNT_CAP) / count;
    count = float(RL_CACHE_COUNT_CAP);
  }
  bool gaussianReset = kStrategy == RL_KEY_GAUSSIAN && varianceOf(count, m2) > cache.gaussReset;
  if (gaussianReset) {
    bool keepBatch = varianceOf(nB, m2B) <= cache.gaussReset;
    count = keepBatch ? min(nB, float(RL_CACHE_COUNT_CAP)) : 0.0;
    mean = keepBatch ? meanB : 0.0;
    m2 = keepBatch ? m2B : 0.0;
  }
  // Never store a NaN or an infinity (both fail these comparisons): such a cell starts over.
  bool sane = mean > -1e37 && mean < 1e37 && m2 >= 0.0 && m2 < 1e37;
  GpuCacheEntry o;
  o.count = sane ? uint(count) : 0u;
  o.mean = sane ? clamp(mean, 0.0, cache.lengthMax) : 0.0;
  o.m2 = sane ? m2 : 0.0;
  o.sigma = sane ? sqrt(varianceOf(count, m2)) : 0.0;
  cache.entries.v[e] = o;
  return gaussianReset || !sane;
}

void main() {
  // Every lane reaches the count, those past the touched entries with nothing to add.
  uint resets = subgroupAdd(mergeTouched(flatInvocationIndex()) ? 1u : 0u);
  if (subgroupElect() && resets > 0u)
    atomicAdd(FrameBuf(pc.frame).f.counters.v[pc.bounce * RL_COUNTER_STRIDE + RL_COUNTER_CACHE_RESETS], resets);
}
