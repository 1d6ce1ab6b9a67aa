// Push constants of the sort shaders, shared by C++ (renderer/reorder/gpu_sort.cpp) and GLSL (shaders/sort_*.comp):
// data and macros only. Buffers are device addresses (uint64 on the host, buffer references in GLSL);
// tests/gpu/test_gpu_sort.cpp asserts the host sizes so the two sides cannot drift.
#ifndef RAYLAB_SORT_TYPES_H
#define RAYLAB_SORT_TYPES_H

#ifdef __cplusplus
#include <cstdint>
namespace raylab::gpu {
using uint = uint32_t;
#define SORT_REF(Type) uint64_t
#else
#define SORT_REF(Type) Type
layout(buffer_reference, scalar) buffer SortUintBuf { uint v[]; };
// Look-back state is read while other work groups write it: every load must reach the device-coherent level.
layout(buffer_reference, scalar) coherent volatile buffer SortStateBuf { uint v[]; };
#endif

// Radix sort: digit width and bins. 8 bits keeps the pass count at 4 for the lab's 30-bit Morton keys
// (31 effective bits with the dead-path bit) and the per-group histograms small enough to scan in one pass.
#define SORT_RADIX_BITS 8
#define SORT_RADIX 256
#define SORT_RADIX_MASK 255u

// Bitonic sort: elements per work group in shared memory (keys and values: 16 KiB, under lavapipe's 32 KiB).
#define SORT_BITONIC_TILE 2048
#define SORT_BITONIC_TILE_LOG 11
#define SORT_BITONIC_GROUP 256

// sort_radix_histogram and sort_radix_scatter (both tile the keys by their group size times keys per
// invocation, specialization constants; a work group takes TILES_PER_GROUP consecutive tiles, in order,
// GpuSorter::Tuning::radixTilesPerGroup, so a hist column counts all of a group's tiles). `hist` holds
// SORT_RADIX * numGroups per-group digit counts, digit-major (hist[digit * numGroups + group]) so that one
// work group scans one digit's row, followed by SORT_RADIX digit totals written by sort_radix_scan.
struct SortRadixPush {
  SORT_REF(SortUintBuf) keysIn;
  SORT_REF(SortUintBuf) valuesIn;
  SORT_REF(SortUintBuf) keysOut;
  SORT_REF(SortUintBuf) valuesOut;
  SORT_REF(SortUintBuf) hist;
  uint count;        // elements to sort
  uint shift;        // lowest key bit of this pass's digit
  uint keyBits;      // 1..32; keys >= 2^keyBits sort as 2^keyBits (after every real key)
  uint numGroups;    // work groups of the whole sort (the width of a hist row): tiles / TILES_PER_GROUP, rounded up
  uint groupOffset;  // first work group of this dispatch (dispatches are split at the device's group limit)
  uint hasCountLimit;  // 1: sort only min(count, countLimit.v[0]) pairs (GpuSorter::record's countLimit)
  SORT_REF(SortUintBuf) countLimit;
};

// sort_radix_scan: each work group scans `rowsPerGroup` digits' rows of `hist` in place (1 on GPUs; more on
// CPU devices, where every work group has a fixed cost).
struct SortScanPush {
  SORT_REF(SortUintBuf) hist;
  uint numGroups;
  uint rowsPerGroup;
};

// sort_bitonic_local (mode 0: full sort of each tile, which is all SortAlgorithm::Tile does; mode 1: the merge
// steps whose distance fits a tile)
// and sort_bitonic_global (one compare-exchange step across tiles).
struct SortBitonicPush {
  SORT_REF(SortUintBuf) keys;
  SORT_REF(SortUintBuf) values;
  uint count;
  uint keyBits;
  uint mode;         // local: 0 sort, 1 merge. global: 0 flip step of block 2^blockLog, 1 half-cleaner
  uint blockLog;     // global flip: log2 of the block size k (pairs p and k-1-p of each block)
  uint distanceLog;  // global half-cleaner: log2 of d (pairs i and i+d within blocks of 2d)
  uint comparators;  // number of compare-exchanges of a global step (padded count / 2)
  uint tileOffset;   // local: first tile of this dispatch (dispatches are split at the group limit)
  uint hasCountLimit;  // local mode 0 (the tile sort): 1: tiles at or past countLimit.v[0] return at once
  SORT_REF(SortUintBuf) countLimit;
};

// sort_copy: copies `count` keys and values (used when the radix pass count is odd).
struct SortCopyPush {
  SORT_REF(SortUintBuf) keysIn;
  SORT_REF(SortUintBuf) valuesIn;
  SORT_REF(SortUintBuf) keysOut;
  SORT_REF(SortUintBuf) valuesOut;
  uint count;
  uint hasCountLimit;  // as SortRadixPush
  SORT_REF(SortUintBuf) countLimit;
};

// sort_small: the whole sort of at most SORT_SMALL_MAX pairs by one work group in shared memory, in one
// dispatch (GpuSorter picks it below that count for the radix sort, issue 36: a radix sort of a few thousand
// pairs is 3 dispatches and 3 barriers a pass, all launch cost). Stable, as the radix sort it stands in for:
// it orders (effective key >> ignoredLowBits, input index). Its three arrays of keys, values and input
// indices take 24 KiB of shared memory.
#define SORT_SMALL_MAX 2048
#define SORT_SMALL_GROUP 256
struct SortSmallPush {
  SORT_REF(SortUintBuf) keys;
  SORT_REF(SortUintBuf) values;
  SORT_REF(SortUintBuf) countLimit;
  uint count;
  uint keyBits;
  uint ignoredLowBits;  // as the radix sort's, already clamped below the sorted bits
  uint hasCountLimit;   // as SortRadixPush: sort only min(count, countLimit.v[0]) pairs
};

// OneSweep variant (decoupled look-back; only on devices with forward progress between work groups): one
// `state` buffer holds, in 32-bit words,
//   [0, 4 * SORT_RADIX)                     the global digit histogram of each pass
//   [SORT_ONESWEEP_COUNTERS + pass]         the tile counter of each pass (tiles are taken in start order)
//   [SORT_ONESWEEP_STATUS + (pass * numTiles + tile) * SORT_RADIX + digit]  look-back status words
// all zeroed before each sort. A status word is a flag (aggregate: this tile's count; inclusive: the count of
// this and all earlier tiles) and a 30-bit count (counts are at most 2^27).
#define SORT_ONESWEEP_MAX_PASSES 4
#define SORT_ONESWEEP_COUNTERS (SORT_ONESWEEP_MAX_PASSES * SORT_RADIX)
#define SORT_ONESWEEP_STATUS (SORT_ONESWEEP_COUNTERS + SORT_ONESWEEP_MAX_PASSES)
#define SORT_STATUS_AGGREGATE 0x40000000u
#define SORT_STATUS_INCLUSIVE 0x80000000u
#define SORT_STATUS_VALUE 0x3FFFFFFFu
#define SORT_ONESWEEP_HIST_KPT 16  // keys per invocation of sort_onesweep_histogram

// sort_onesweep_histogram (keysIn, state, count, shift, keyBits, passes, the count limit) and
// sort_onesweep_pass (all but passes).
struct SortOneSweepPush {
  SORT_REF(SortUintBuf) keysIn;
  SORT_REF(SortUintBuf) valuesIn;
  SORT_REF(SortUintBuf) keysOut;
  SORT_REF(SortUintBuf) valuesOut;
  SORT_REF(SortStateBuf) state;
  uint count;
  uint shift;     // lowest key bit of this pass's digit (the histogram: of pass 0's; pass p's is shift + 8p)
  uint keyBits;
  uint numTiles;  // tiles covering `count` (the width of a pass's status rows)
  uint pass;
  uint passes;
  uint hasCountLimit;  // as SortRadixPush: sort only min(count, countLimit.v[0]) pairs
  uint unused;
  SORT_REF(SortUintBuf) countLimit;
};

// The key the sort compares: the caller guarantees key < 2^keyBits or key == 0xFFFFFFFF (a dead path);
// clamping to 2^keyBits makes dead keys sort after every live key without tying with the largest live
// one, at the price of one more key bit (keyBits + 1 bits are sorted when keyBits < 32).
#ifdef __cplusplus
inline uint sortEffectiveKey(uint key, uint keyBits) {
  return keyBits >= 32 ? key : (key < (1u << keyBits) ? key : (1u << keyBits));
}
}  // namespace raylab::gpu
#else
uint sortEffectiveKey(uint key, uint keyBits) {
  return keyBits >= 32 ? key : min(key, 1u << keyBits);
}
// The pairs a radix dispatch sorts: `count`, or fewer when the device holds a smaller bound (the live prefix).
uint sortLimitedCount(uint count, uint hasCountLimit, SortUintBuf countLimit) {
  return hasCountLimit != 0u ? min(count, countLimit.v[0]) : count;
}
#endif

#endif
