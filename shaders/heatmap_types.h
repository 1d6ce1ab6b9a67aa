// Heatmap pass push constants, shared by C++ and GLSL (see renderer/heatmap_pass.h).
#ifndef RAYLAB_HEATMAP_TYPES_H
#define RAYLAB_HEATMAP_TYPES_H

#include "shared_types.h"
#include "key_types.h"

#ifdef __cplusplus
namespace raylab::gpu {
#endif

// Values of HeatmapView (renderer/settings.h), in the same order.
#define RL_HEAT_SORT_KEY 1u
#define RL_HEAT_CELL_HIT 2u
#define RL_HEAT_STEPS 3u
#define RL_HEAT_WARP 4u
#define RL_HEAT_CACHE_MEAN 5u
#define RL_HEAT_CACHE_VARIANCE 6u
// A pixel no path of the shown bounce wrote to (finished earlier, or no key at that bounce).
#define RL_HEAT_EMPTY 0xFFFFFFFFu

struct HeatmapPush {
  RL_REF(FrameBuf) frame;
  RL_REF(KeyParamsBuf) keyParams;  // grid and cache (zero when no key stage is active)
  RL_REF(UintBuf) keys;            // sort keys in the current set's order (SortKey view)
  RL_REF(UintBuf) heat;            // per pixel: float bits of the value (key bits for SortKey), or EMPTY
  RL_REF(UintBuf) range;           // [0] min, [1] max of the written values (float bits, values >= 0)
  uint view;
  uint stateSet;
  uint megakernel;  // 1: paths are in id order and hits.steps holds whole-path totals
  uint hasKeyParams;
  uint hasCache;  // 1: keyParams' length cache exists (its buffer addresses are zero otherwise)
  uint pad;       // to a multiple of 8 bytes, as C++ lays the struct out
};

#ifdef __cplusplus
static_assert(sizeof(HeatmapPush) == 64);
}  // namespace raylab::gpu
#endif
#endif
