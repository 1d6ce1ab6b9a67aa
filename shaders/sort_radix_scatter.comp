#version 460
// Radix sort, step (c) of a pass: ranks the keys of one tile stably by digit and writes keys and values to
// their global places. Ranking is a warp-level multisplit: each subgroup walks its contiguous slice of the
// tile in order, finds the lanes holding the same digit with one ballot per digit bit, and keeps a running
// count per (subgroup, digit) in shared memory. A column scan over subgroups and a scan over digits then
// give each key its place in the tile sorted by digit; the tile is reordered in shared memory first so that
// the global writes of each digit's run are contiguous (coalesced).
// Values are loaded only once the keys are ranked, which keeps register pressure (and so occupancy) down.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_ballot : require
#include "sort_types.h"

layout(local_size_x_id = 0) in;
// The device's subgroup size as the host sees it: sizes the per-subgroup histograms and the slices.
layout(constant_id = 1) const uint SG_SIZE = 32;
layout(constant_id = 2) const uint KPT = 15;  // keys per invocation
layout(push_constant, scalar) uniform Push { SortRadixPush pc; };

#include "sort_scan.glsl"

const uint GROUP = gl_WorkGroupSize.x;  // the host keeps it a divisor of SORT_RADIX and a multiple of SG_SIZE
const uint NUM_SG = GROUP / SG_SIZE;
const uint TILE = GROUP * KPT;
const uint HIST_WORDS = NUM_SG * SORT_RADIX;
const uint DIGITS_PER_THREAD = SORT_RADIX / GROUP;
// The per-subgroup histograms are dead once every key knows its place, so the reordered tile (keys, then
// values) reuses their memory.
shared uint sMem[2 * TILE > HIST_WORDS ? 2 * TILE : HIST_WORDS];
shared uint sLocalStart[SORT_RADIX];   // first place of each digit in the tile
shared uint sGlobalShift[SORT_RADIX];  // global place of tile element j is sGlobalShift[digit] + j

uint digitOf(uint key) { return (sortEffectiveKey(key, pc.keyBits) >> pc.shift) & SORT_RADIX_MASK; }

void main() {
  uint t = gl_LocalInvocationID.x;
  uint sg = gl_SubgroupID;
  uint lane = gl_SubgroupInvocationID;
  uint group = gl_WorkGroupID.x + pc.groupOffset;
  uint tileBegin = group * TILE;
  uint tileCount = min(TILE, pc.count - tileBegin);
  uint sliceBegin = tileBegin + sg * SG_SIZE * KPT;

  for (uint i = t; i < HIST_WORDS; i += GROUP) sMem[i] = 0;

  // Where each digit starts in the output: digits before it (scan of the totals) plus the same digit in
  // earlier tiles (the scanned table). Each invocation owns DIGITS_PER_THREAD consecutive digits.
  uint firstDigit = t * DIGITS_PER_THREAD;
  uint totalsBase = SORT_RADIX * pc.numGroups;
  uint mine = 0;
  for (uint k = 0; k < DIGITS_PER_THREAD; ++k) mine += pc.hist.v[totalsBase + firstDigit + k];
  uint unused;
  uint digitStart = groupExclusiveAdd(mine, unused);
  for (uint k = 0; k < DIGITS_PER_THREAD; ++k) {
    uint d = firstDigit + k;
    sGlobalShift[d] = digitStart + pc.hist.v[d * pc.numGroups + group];
    digitStart += pc.hist.v[totalsBase + d];
  }

  uint keys[KPT];
  uint place[KPT];
  for (uint k = 0; k < KPT; ++k) {
    uint idx = sliceBegin + k * SG_SIZE + lane;
    if (idx < pc.count) keys[k] = pc.keysIn.v[idx];
  }
  barrier();  // histograms cleared

  // Rank within the subgroup's slice, in element order (k-major, then lane): this is what makes it stable.
  uint histBase = sg * SORT_RADIX;
  for (uint k = 0; k < KPT; ++k) {
    bool valid = sliceBegin + k * SG_SIZE + lane < pc.count;
    uint d = valid ? digitOf(keys[k]) : 0u;
    uvec4 peers = subgroupBallot(valid);
    for (uint b = 0; b < SORT_RADIX_BITS; ++b) {
      bool bit = ((d >> b) & 1u) != 0u;
      uvec4 votes = subgroupBallot(bit);
      peers &= bit ? votes : ~votes;
    }
    uint below = subgroupBallotExclusiveBitCount(peers);
    uint before = valid ? sMem[histBase + d] : 0u;
    // Every peer reads the running count before the lowest peer advances it.
    subgroupMemoryBarrierShared();
    subgroupBarrier();
    if (valid && below == 0u) sMem[histBase + d] = before + subgroupBallotBitCount(peers);
    subgroupMemoryBarrierShared();
    subgroupBarrier();
    place[k] = before + below;
  }
  barrier();

  // Column scan: counts per (subgroup, digit) become the start of the subgroup's run within the digit.
  uint runs[DIGITS_PER_THREAD];
  mine = 0;
  for (uint k = 0; k < DIGITS_PER_THREAD; ++k) {
    uint d = firstDigit + k;
    uint run = 0;
    for (uint s = 0; s < NUM_SG; ++s) {
      uint c = sMem[s * SORT_RADIX + d];
      sMem[s * SORT_RADIX + d] = run;
      run += c;
    }
    runs[k] = run;
    mine += run;
  }
  uint localStart = groupExclusiveAdd(mine, unused);
  for (uint k = 0; k < DIGITS_PER_THREAD; ++k) {
    uint d = firstDigit + k;
    sLocalStart[d] = localStart;
    sGlobalShift[d] -= localStart;
    localStart += runs[k];
  }
  barrier();

  uint values[KPT];
  for (uint k = 0; k < KPT; ++k) {
    uint idx = sliceBegin + k * SG_SIZE + lane;
    if (idx < pc.count) {
      values[k] = pc.valuesIn.v[idx];
      uint d = digitOf(keys[k]);
      place[k] += sLocalStart[d] + sMem[histBase + d];
    }
  }
  barrier();  // every place computed before the histograms are overwritten by the tile

  for (uint k = 0; k < KPT; ++k) {
    if (sliceBegin + k * SG_SIZE + lane < pc.count) {
      sMem[place[k]] = keys[k];
      sMem[TILE + place[k]] = values[k];
    }
  }
  barrier();
  for (uint k = 0; k < KPT; ++k) {
    uint j = k * GROUP + t;
    if (j < tileCount) {
      uint key = sMem[j];
      uint dest = sGlobalShift[digitOf(key)] + j;
      pc.keysOut.v[dest] = key;
      pc.valuesOut.v[dest] = sMem[TILE + j];
    }
  }
}
