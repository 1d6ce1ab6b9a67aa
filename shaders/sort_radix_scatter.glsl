// Radix sort, step (c) of a pass (reduce-then-scan), included by sort_radix_scatter.comp and by
// sort_radix_scatter_partitioned.comp (which defines RL_RANK_PARTITIONED first: the tile ranked by
// subgroupPartitionNV instead of ballots). Ranks the keys of each of its tiles (TILES_PER_GROUP
// consecutive ones, in order) stably by digit and writes keys and values to their global places
// (sort_radix_tile.glsl). Where a tile's run of a digit starts comes from the scanned count table (digits
// before it, the scan of the digit totals, plus the same digit in earlier work groups) and the group's earlier
// tiles. No work group waits on another.
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_ballot : require
#include "spec_ids.h"
#include "sort_types.h"

layout(local_size_x_id = RL_SPEC_GROUP_SIZE) in;
// The device's subgroup size as the host sees it: sizes the per-subgroup histograms and the slices.
layout(constant_id = RL_SPEC_SUBGROUP_SIZE) const uint SG_SIZE = 32;
layout(constant_id = RL_SPEC_KEYS_PER_THREAD) const uint KPT = 15;  // keys per invocation
layout(constant_id = RL_SPEC_TILES_PER_GROUP) const uint TILES_PER_GROUP = 1;
layout(push_constant, scalar) uniform Push { SortRadixPush pc; };

#include "sort_scan.glsl"
#include "sort_radix_tile.glsl"

void main() {
  uint group = gl_WorkGroupID.x + pc.groupOffset;
  uint limit = sortLimitedCount(pc.count, pc.hasCountLimit, pc.countLimit);
  // Groups whose tiles are all past a device-side count limit have nothing to place (their column is zero).
  if (group * TILES_PER_GROUP * TILE >= limit) return;
  uint totalsBase = SORT_RADIX * pc.numGroups;
  uint totals[DIGITS_PER_THREAD];
  for (uint k = 0; k < DIGITS_PER_THREAD; ++k) totals[k] = pc.hist.v[totalsBase + firstOwnedDigit() + k];
  uint starts[DIGITS_PER_THREAD];
  digitStarts(totals, starts);
  // Where the group's next tile's run of each owned digit starts: after the digits before it, the same digit
  // in earlier groups, and in this group's earlier tiles.
  uint next[DIGITS_PER_THREAD];
  for (uint k = 0; k < DIGITS_PER_THREAD; ++k) next[k] = starts[k] + pc.hist.v[(firstOwnedDigit() + k) * pc.numGroups + group];
  for (uint tile = group * TILES_PER_GROUP; tile < (group + 1) * TILES_PER_GROUP; ++tile) {
    if (!tileRank(tile, limit)) break;  // uniform; tileRank ends with a barrier
    for (uint k = 0; k < DIGITS_PER_THREAD; ++k) {
      uint d = firstOwnedDigit() + k;
      sGlobalShift[d] = next[k] - sLocalStart[d];
      next[k] += tileDigitCount[k];
    }
    tileScatter();
    // The tile's shared memory read before the next tile's ranking clears it; none after the group's last
    // tile (the condition is the same for the whole group), so one tile a group runs as before.
    if (tile + 1 < (group + 1) * TILES_PER_GROUP) barrier();
  }
}
