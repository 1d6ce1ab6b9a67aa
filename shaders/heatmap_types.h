// Heatmap pass push constants and named slots, shared by C++ and GLSL (see renderer/heatmap/heatmap_pass.h).
#ifndef RAYLAB_HEATMAP_TYPES_H
#define RAYLAB_HEATMAP_TYPES_H

#include "shared_types.h"
#include "key_types.h"

#ifdef __cplusplus
namespace raylab::gpu {
#endif

// Values of HeatmapView (renderer/settings/settings.h), in the same order.
#define RL_HEAT_SORT_KEY 1u
#define RL_HEAT_CELL_HIT 2u
#define RL_HEAT_STEPS 3u
#define RL_HEAT_WARP 4u
#define RL_HEAT_CACHE_MEAN 5u
#define RL_HEAT_CACHE_VARIANCE 6u
// Values of HeatmapKeyColour, in the same order.
#define RL_HEAT_KEY_CELL 0u
#define RL_HEAT_KEY_RANK 1u
#define RL_HEAT_KEY_HASH 2u

// Per-pixel sentinels of the heat buffer (a value is the float bits of a non-negative float, or key bits).
// No path: no path of this pixel reached the shown bounce (it finished earlier, or no keys were made).
#define RL_HEAT_EMPTY 0xFFFFFFFFu
// No value: the path is there but the view has nothing for it: its length-cache entry is empty (never
// learned) for the cache views, or it escaped / has no estimate for cell-hit. Drawn in its own colour.
#define RL_HEAT_NO_VALUE 0xFFFFFFFEu

// Slots of the range buffer (host-visible, read after the frame).
#define RL_HEAT_RANGE_MIN 0u       // float bits (key bits for sort keys) of the smallest value written
#define RL_HEAT_RANGE_MAX 1u       // ... of the largest
#define RL_HEAT_RANGE_VALUES 2u    // pixels given a value
#define RL_HEAT_RANGE_NO_VALUE 3u  // pixels given RL_HEAT_NO_VALUE
// Sort keys by cell: the smallest and largest cell coordinate per axis the frame's keys encode (3 words
// each), so the position colours stretch over the part of the grid the view sees, not the whole scene.
#define RL_HEAT_RANGE_CELL_MIN 4u
#define RL_HEAT_RANGE_CELL_MAX 7u
#define RL_HEAT_RANGE_SLOTS 10u

// Per pixel, beside the value: what the hover readout shows (path id, sort key, grid cell, octant).
#define RL_HEAT_PROBE_PATH 0u  // path id (RL_DEAD_PATH: no path)
#define RL_HEAT_PROBE_KEY 1u   // the path's sort key at the shown bounce (RL_DEAD_KEY: none)
#define RL_HEAT_PROBE_CELL 2u  // sort key view: the key's cell; others: the ray origin's cell (RL_HEAT_NO_CELL: none)
#define RL_HEAT_PROBE_OCTANT 3u  // the ray direction's octant (with the origin cell: the cache entry looked up)
#define RL_HEAT_PROBE_STRIDE 4u
#define RL_HEAT_NO_CELL 0xFFFFFFFFu
// A cell packed in one word, 10 bits an axis (SettingLimits::kMaxGridCellsPerAxis = 1024).
#define RL_HEAT_CELL_BITS 10u

// What a gather dispatch writes.
#define RL_HEAT_GATHER_VALUE 0u  // the view's value (after the trace, or the key stage for sort keys)
#define RL_HEAT_GATHER_RANK 1u   // sort keys by rank: after the sort, a path's sorted position is its rank

struct HeatmapPush {
  RL_REF(FrameBuf) frame;
  RL_REF(KeyParamsBuf) keyParams;  // grid and cache (zero when no key stage is active)
  RL_REF(UintBuf) keys;            // sort keys in the current set's order (SortKey view)
  RL_REF(UintBuf) heat;            // per pixel: float bits of the value (key bits for SortKey), or a sentinel
  RL_REF(UintBuf) probe;           // per pixel: RL_HEAT_PROBE_STRIDE words
  RL_REF(UintBuf) range;           // RL_HEAT_RANGE_* slots
  uint view;
  uint stateSet;
  uint megakernel;  // 1: paths are in id order and hits.steps holds whole-path totals
  uint hasKeyParams;
  uint hasCache;    // 1: keyParams' length cache exists (its buffer addresses are zero otherwise)
  uint gather;      // RL_HEAT_GATHER_*
  uint keyColour;   // RL_HEAT_KEY_*
  uint strategy;    // RL_KEY_*: how a key encodes its cell
  uint logScale;    // 1: values map onto the ramp logarithmically
  uint rangeFixed;  // 1: colour range is [rangeMin, rangeMax] (locked, or the view's natural range)
  float rangeMin;
  float rangeMax;
};

#ifdef __cplusplus
static_assert(sizeof(HeatmapPush) == 96);
}  // namespace raylab::gpu
#endif
#endif
