// Structs shared by the key stage's C++ side and its shaders (keys.comp, key_oracle.comp, key_learn.comp,
// key_merge.comp): the grid, the length cache and the push constants. Data and macros only, scalar block
// layout; tests/cpu/test_key_functions.cpp asserts the host sizes.
#ifndef RAYLAB_KEY_TYPES_H
#define RAYLAB_KEY_TYPES_H

#include "shared_types.h"

#ifdef __cplusplus
namespace raylab::gpu {
using uvec3 = glm::uvec3;
#endif

// Strategy ids, in the order of raylab::KeyStrategy (specialization constant 1 of the key shaders).
#define RL_KEY_NONE 0u
#define RL_KEY_DEAD_LAST 1u
#define RL_KEY_FIXED 2u
#define RL_KEY_AVERAGE 3u
#define RL_KEY_EMA 4u
#define RL_KEY_GAUSSIAN 5u
#define RL_KEY_ORIGIN 6u
#define RL_KEY_DIRECTION 7u
#define RL_KEY_ORIGIN_DIRECTION 8u
#define RL_KEY_TWO_POINT 9u
#define RL_KEY_ORACLE 10u

// Combined keys (origin-direction, two-point) keep at most this many bits: the top one of 32 stays free so
// the dead key is larger than any live key even when the sort only looks at keyBits bits.
#define RL_KEY_MAX_SPATIAL_BITS 31u
// Two-point keys keep only the top 23 bits of their interleaved code: with the sorter's clamp bit for the
// dead key they fit three 8-bit radix passes instead of four (PathSorter passes keyBits - 1). H200,
// 2048x1024, 1 spp, two-point, always sorting: sort 0.21 -> 0.17 ms a bounce; frame 4 bounces hall 4.89 ->
// 4.79, alley 4.29 -> 4.26, openings 2.14 -> 2.01, Sponza 8.07 -> 7.98 ms; 8 bounces hall 9.93 -> 9.69,
// Sponza 14.25 -> 13.98 ms. Truncating alone (and still sorting 25 bits, 4 passes) changed nothing.
#define RL_KEY_TWO_POINT_BITS 23u
// Direction octants per occupied cache cell.
#define RL_OCTANTS 8u
// The Gaussian cache rejects outliers only once a cell holds this many samples: below it, mean and sigma
// are too noisy to call anything an outlier.
#define RL_GAUSS_MIN_SAMPLES 8u
// Cache sample counts saturate here (float weights stay exact; the mean becomes a slow moving average).
#define RL_CACHE_COUNT_CAP 16777216u

// The key grid: cell = clamp(floor((p - boundsMin) * invCellSize), 0, cells - 1), Morton code of the cell.
struct GpuKeyGrid {
  vec3 boundsMin;
  uint spatialBits;  // bits the live keys of the current strategy use (keyBits - 1)
  vec3 invCellSize;
  uint gridBits;     // bits.x + bits.y + bits.z
  uvec3 cells;
  uint maxAxisBits;  // max(bits): octahedral bits per axis in origin-direction keys
  uvec3 bits;        // ceil(log2(cells)) per axis
  uint cacheShift;   // cache cells are key cells >> cacheShift (coarser when the scene occupies many cells)
  uvec3 cacheCells;  // cache cells per axis
  uint pad0;
};

// One (occupied cell, octant) entry of the length cache.
struct GpuCacheEntry {
  uint count;   // samples folded in (saturates at RL_CACHE_COUNT_CAP); 0: no data, use the fixed length
  float mean;   // mean length
  float m2;     // sum of squared deviations (Gaussian only)
  float sigma;  // sqrt(m2 / (count - 1)), kept so the key shader needs no square root (Gaussian only)
};

// Samples of one bounce for one entry, accumulated with 32-bit integer atomics: lengths are quantized to
// fixed point relative to the entry's current mean, so sums are exact and the result does not depend on
// the order threads add in. 64-bit sums are two words with a software carry.
struct GpuCacheBatch {
  uint count;
  uint sumLo;  // sum of q (two's complement, 64 bits)
  uint sumHi;
  uint sqLo;   // sum of q^2 (unsigned, 64 bits)
  uint sqHi;
};

#ifndef __cplusplus
layout(buffer_reference, scalar) buffer CacheEntryBuf { GpuCacheEntry v[]; };
layout(buffer_reference, scalar) buffer CacheBatchBuf { GpuCacheBatch v[]; };
#endif

// The length cache: an open-addressing hash table (linear probing) from cache-cell index + 1 to a compact
// cell id, entries at id * 8 + octant. Built on the host from the cells the scene's triangles touch.
struct GpuLengthCache {
  RL_REF(UintBuf) slotKeys;    // cache-cell index + 1; 0: empty slot
  RL_REF(UintBuf) slotValues;  // compact cell id
  RL_REF(CacheEntryBuf) entries;
  RL_REF(CacheBatchBuf) batches;
  RL_REF(UintBuf) touched;     // [0] entries touched this bounce, [1] outliers rejected so far, [2..] ids
  uint slotMask;               // slot count - 1 (a power of two)
  uint entryCount;
  float lengthMax;             // lengths are clamped to [0, lengthMax] before they are learned or used
  float unit;                  // fixed-point step of a quantized length
  float invUnit;
  float sigmaFloor;            // outlier test uses max(sigma, sigmaFloor): a zero-variance cell is not frozen
  float emaAlpha;
  float gaussOutlier;
  float gaussReset;
  uint pad0;
};

struct GpuKeyParams {
  GpuKeyGrid grid;
  GpuLengthCache cache;
  RL_REF(FloatBuf) oracleT;  // per path: hit distance found by key_oracle.comp (negative: miss)
  float fixedLength;         // fixedFactor * the scene's largest extent
  uint pad0;
};

#ifndef __cplusplus
layout(buffer_reference, scalar) buffer KeyParamsBuf { GpuKeyParams p; };
#endif

// Push constants of the rt megakernel with shader execution reordering (megakernel_ser.rgen): the frame
// block, and the key parameters whose key function (specialization constant 2) gives the coherence hint:
// the key's top hintBits bits (key >> hintShift). Without a hint the threads are reordered by hit only.
struct RtSerPush {
  RL_REF(FrameBuf) frame;
  RL_REF(KeyParamsBuf) keyParams;  // 0 without a hint
  uint hintShift;
  uint hintBits;
};

// keys.comp and key_oracle.comp: one thread per path of the current state set.
struct KeyPush {
  RL_REF(FrameBuf) frame;
  RL_REF(KeyParamsBuf) params;
  RL_REF(UintBuf) keys;    // out: sort key per path
  RL_REF(UintBuf) values;  // out: path index (the sort's payload)
  uint stateSet;
  uint bounce;
  uint count;
  uint pad0;
};

// key_learn.comp (one thread per path) and key_merge.comp (one thread per touched entry).
struct KeyLearnPush {
  RL_REF(FrameBuf) frame;
  RL_REF(KeyParamsBuf) params;
  uint stateSet;
  uint bounce;
  uint count;
  uint learnEvery;  // Settings::learnEvery: slots i with (i + frameIndex + bounce) % learnEvery == 0 learn
};

#ifdef __cplusplus
static_assert(sizeof(RtSerPush) == 24);
static_assert(sizeof(KeyPush) == 48);
static_assert(sizeof(KeyLearnPush) == 32);
}  // namespace raylab::gpu
#endif
#endif
