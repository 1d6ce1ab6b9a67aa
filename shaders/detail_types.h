// The detailed statistics of a frame as GPU reductions (detail_warps.comp, detail_prediction.comp,
// detail_keys.comp, detail_cache.comp): each pass reads a bounce's per-path arrays where they lie and adds
// integer sums to that bounce's GpuDetailSums, so the host reads a few kilobytes after the frame instead of
// walking millions of paths (the host walk idled an H200 for 0.6 s a frame at 8.4M paths, and its clocks
// dropped: every stage read 2-5x slower). renderer/detail_sums.cpp is the plain C++ twin of every pass and
// turns sums into figures for both. Integer sums do not depend on the order threads add in: the figures are
// the same whichever way a frame is recorded (whole, or in steps).
#ifndef RAYLAB_DETAIL_TYPES_H
#define RAYLAB_DETAIL_TYPES_H

#include "key_types.h"

#ifdef __cplusplus
namespace raylab::gpu {
#endif

// Virtual warp width of the warp efficiency (device-independent: renderer/warp_efficiency.h).
#define RL_VIRTUAL_WARP 32u
// Work-group size of the detail passes: a multiple of RL_VIRTUAL_WARP, so a group's slots are whole warps.
#define RL_DETAIL_GROUP_SIZE 256u
// At most this many groups; each loops over the slots (fewer groups flush fewer partial sums).
#define RL_DETAIL_MAX_GROUPS 1024u

// Prediction errors (|predicted - actual length| / scene diagonal) are summed in fixed point with this many
// fraction bits, each clamped to RL_DETAIL_ERROR_MAX diagonals first (a longer miss is a junk prediction),
// so a frame of up to 2^27 paths sums into 64 bits exactly.
#define RL_DETAIL_ERROR_FRACTION_BITS 24
#define RL_DETAIL_ERROR_MAX 4096.0
// The median comes from a histogram of errors binned by their float bits: 2^RL_DETAIL_BIN_MANTISSA_BITS bins
// per octave from 2^RL_DETAIL_BIN_MIN_EXPONENT (about 1e-6 diagonals) up, so a bin's midpoint is within
// 2^-(MANTISSA_BITS + 1) (0.8%) of any error in it. Bin 0 holds the smaller errors (a median there reads 0),
// the last bin every error from just under 2^(MIN + RL_DETAIL_BIN_OCTAVES) on.
#define RL_DETAIL_BIN_MANTISSA_BITS 6u
#define RL_DETAIL_BIN_MIN_EXPONENT (-20)
#define RL_DETAIL_BIN_OCTAVES 32u
#define RL_DETAIL_ERROR_BINS (RL_DETAIL_BIN_OCTAVES << RL_DETAIL_BIN_MANTISSA_BITS)
// Distinct keys are counted in a bitmap of at most 2^RL_DETAIL_KEY_BITMAP_BITS bits (128 MiB); wider live
// keys (origin-direction on grids past 2^30 cells and directions) drop their lowest bits first.
#define RL_DETAIL_KEY_BITMAP_BITS 30u

// One bounce's sums; 64-bit sums are two words (lo, hi) with a software carry (64-bit atomics are optional).
struct GpuDetailSums {
  uint warpWorkLo;   // traversal steps summed over the slots (dispatch order)
  uint warpWorkHi;
  uint warpSlotsLo;  // RL_VIRTUAL_WARP x the largest steps of each virtual warp, summed over the warps
  uint warpSlotsHi;
  uint livePaths;    // live paths of the bounce's rays
  uint evaluated;    // live, with a prediction and a hit: the paths the error figures describe
  uint misses;       // live with a prediction but no hit
  uint sameCell;     // evaluated paths whose predicted end point lies in the actual end point's grid cell
  uint errorLo;      // sum of the evaluated paths' errors, fixed point (RL_DETAIL_ERROR_FRACTION_BITS)
  uint errorHi;
  uint distinctKeys;  // distinct live keys made for the bounce's rays
  uint cacheUsed;    // length-cache entries holding samples, at the end of the frame (bounce 0's sums only)
  uint errorBins[RL_DETAIL_ERROR_BINS];
};

#ifndef __cplusplus
layout(buffer_reference, scalar) buffer DetailSumsBuf { GpuDetailSums s; };
#endif

// Push constants of every detail pass (each reads the fields its comment names).
struct DetailPush {
  RL_REF(FrameBuf) frame;          // prediction: the frame block (the bounce's state set and hits)
  RL_REF(KeyParamsBuf) keyParams;  // prediction: the key grid; cache: the length cache
  RL_REF(UintBuf) values;          // warps: traversal steps per slot; keys: the sort keys
  RL_REF(UintBuf) bitmap;          // keys: one bit per key value, cleared before the pass
  RL_REF(DetailSumsBuf) sums;      // the bounce's sums
  uint count;                      // slots (warps, prediction, keys) or cache entries (cache)
  uint stateSet;                   // prediction: the state set holding the bounce's rays
  uint keyShift;                   // keys: low bits dropped so a live key fits the bitmap
  float invDiagonal;               // prediction: 1 / the scene diagonal
};

#ifdef __cplusplus
}  // namespace raylab::gpu
#endif

#endif
