#version 460
// OneSweep radix sort, one pass in one dispatch (Adinets & Merrill, 2022): each work group takes the next tile
// from a counter, ranks it (sort_radix_tile.glsl), publishes its per-digit counts, then looks back over the
// earlier tiles' published counts until it meets an inclusive prefix. A work group only ever waits on tiles
// taken before its own, i.e. on work groups already running: this needs forward progress between running
// work groups, which GPUs give and CPU implementations do not promise (lavapipe even ends any shader's loops
// after 65535 iterations in all, which a spinning look-back exceeds); the host selects this variant only
// where it is known to hold.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_memory_scope_semantics : require
#include "spec_ids.h"
#include "sort_types.h"

layout(local_size_x_id = RL_SPEC_GROUP_SIZE) in;
layout(constant_id = RL_SPEC_SUBGROUP_SIZE) const uint SG_SIZE = 32;
layout(constant_id = RL_SPEC_KEYS_PER_THREAD) const uint KPT = 15;
layout(push_constant, scalar) uniform Push { SortOneSweepPush pc; };

#include "sort_scan.glsl"
#include "sort_radix_tile.glsl"

shared uint sTile;

void main() {
  if (gl_LocalInvocationID.x == 0) sTile = atomicAdd(pc.state.v[SORT_ONESWEEP_COUNTERS + pc.pass], 1u);
  barrier();
  uint tile = sTile;
  // Tiles cover pc.count. Past a device-side bound a tile has nothing to place, and only later tiles (past
  // it too) would read its counts, so it returns without publishing any.
  if (!tileRank(tile, sortLimitedCount(pc.count, pc.hasCountLimit, pc.countLimit))) return;

  uint statusRow = SORT_ONESWEEP_STATUS + pc.pass * pc.numTiles * SORT_RADIX;
  uint totals[DIGITS_PER_THREAD];
  for (uint k = 0; k < DIGITS_PER_THREAD; ++k) {
    uint d = firstOwnedDigit() + k;
    // Publish early so later tiles can use this one's count while it looks back itself.
    atomicExchange(pc.state.v[statusRow + tile * SORT_RADIX + d],
                   (tile == 0u ? SORT_STATUS_INCLUSIVE : SORT_STATUS_AGGREGATE) | tileDigitCount[k]);
    totals[k] = pc.state.v[pc.pass * SORT_RADIX + d];
  }
  uint starts[DIGITS_PER_THREAD];
  digitStarts(totals, starts);

  for (uint k = 0; k < DIGITS_PER_THREAD; ++k) {
    uint d = firstOwnedDigit() + k;
    uint before = 0;  // keys with digit d in earlier tiles
    if (tile > 0u) {
      uint look = tile - 1u;
      for (;;) {
        uint status = atomicLoad(pc.state.v[statusRow + look * SORT_RADIX + d], gl_ScopeDevice,
                                 gl_StorageSemanticsBuffer, gl_SemanticsRelaxed);
        if ((status & (SORT_STATUS_AGGREGATE | SORT_STATUS_INCLUSIVE)) == 0u) continue;  // not published yet
        before += status & SORT_STATUS_VALUE;
        if ((status & SORT_STATUS_INCLUSIVE) != 0u) break;
        --look;  // tile 0 publishes an inclusive count, so this stops there at the latest
      }
      atomicExchange(pc.state.v[statusRow + tile * SORT_RADIX + d],
                     SORT_STATUS_INCLUSIVE | (before + tileDigitCount[k]));
    }
    sGlobalShift[d] = starts[k] + before - sLocalStart[d];
  }
  tileScatter();
}
