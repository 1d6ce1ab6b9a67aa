// The tile work shared by the two radix scatters (sort_radix_scatter: reduce-then-scan; sort_onesweep_pass:
// decoupled look-back): rank one tile's keys stably by digit, then write keys and values to their global
// places once the caller has said where each digit's run of this tile starts (sGlobalShift).
//
// Ranking is a warp-level multisplit: each subgroup walks its contiguous slice of the tile in order, finds the
// lanes holding the same digit with one ballot per digit bit (or one subgroupPartitionNV where the includer
// defines RL_RANK_PARTITIONED), and keeps a running count per (subgroup, digit)
// in shared memory. A column scan over subgroups and a scan over digits give each key its place in the tile
// sorted by digit; the tile is reordered in shared memory first so that the global writes of each digit's run
// are contiguous (coalesced). Values are loaded only after ranking, which keeps register pressure down.
//
// On an H100 (docs/results/scatter-bound, whose scatter-variants.patch holds each variant) no one part bounds
// the scatter: at 8.4M uniform pairs writing 256 digit runs of about 8 keys a tile costs about 20% of it against
// contiguous writes, the ranking about 26%, and the rest moves 1.8 TB/s. It takes 69 registers, so 3 groups of
// 256 an SM, and none of these paid: the lowest lane of a digit advancing its count by an atomic and a shuffle
// handing it on (no subgroup barriers; level), the values loaded with the keys or the next tile's keys prefetched
// (-0.6% to +3%), the reordered tile behind the histograms filled as places become known (1.9x slower; likely its
// loads no longer overlap), 4 keys an invocation or groups of 128 (12-61% slower at 2.1M-8.4M pairs).
//
// The includer declares the push block `pc` (keysIn, valuesIn, keysOut, valuesOut, shift, keyBits),
// the specialization constants SG_SIZE (id 1) and KPT (id 2), and includes sort_scan.glsl.
#ifndef RAYLAB_SORT_RADIX_TILE_GLSL
#define RAYLAB_SORT_RADIX_TILE_GLSL

const uint GROUP = gl_WorkGroupSize.x;  // the host keeps it a divisor of SORT_RADIX and a multiple of SG_SIZE
const uint NUM_SG = GROUP / SG_SIZE;
const uint TILE = GROUP * KPT;
const uint HIST_WORDS = NUM_SG * SORT_RADIX;
const uint DIGITS_PER_THREAD = SORT_RADIX / GROUP;  // each invocation owns this many consecutive digits
// The per-subgroup histograms are dead once every key knows its place, so the reordered tile (keys, then
// values) reuses their memory.
shared uint sMem[2 * TILE > HIST_WORDS ? 2 * TILE : HIST_WORDS];
shared uint sLocalStart[SORT_RADIX];   // first place of each digit in the tile
shared uint sGlobalShift[SORT_RADIX];  // set by the includer: global place of tile element j is sGlobalShift[digit] + j

uint tileBegin;
uint tileLimit;                        // pairs sorted (pc.count, or the device-side limit)
uint sliceBegin;                       // this subgroup's slice
uint tileKeys[KPT];
uint tilePlace[KPT];
uint tileDigitCount[DIGITS_PER_THREAD];  // this tile's count of each owned digit

uint digitOf(uint key) { return (sortEffectiveKey(key, pc.keyBits) >> pc.shift) & SORT_RADIX_MASK; }
uint firstOwnedDigit() { return gl_LocalInvocationID.x * DIGITS_PER_THREAD; }
bool slotValid(uint k) { return sliceBegin + k * SG_SIZE + gl_SubgroupInvocationID < tileLimit; }

// Ends with a barrier; afterwards sLocalStart and tileDigitCount are set. `limit`: the pairs sorted; a tile
// at or past it returns at once (the whole group: it is uniform), so call tileScatter only if this is true.
bool tileRank(uint tile, uint limit) {
  tileLimit = limit;
  if (tile * TILE >= limit) return false;
  uint t = gl_LocalInvocationID.x;
  uint sg = gl_SubgroupID;
  uint lane = gl_SubgroupInvocationID;
  tileBegin = tile * TILE;
  sliceBegin = tileBegin + sg * SG_SIZE * KPT;
  for (uint i = t; i < HIST_WORDS; i += GROUP) sMem[i] = 0;
  for (uint k = 0; k < KPT; ++k)
    if (slotValid(k)) tileKeys[k] = pc.keysIn.v[sliceBegin + k * SG_SIZE + lane];
  barrier();  // histograms cleared

  // In element order (k-major, then lane): this is what makes the sort stable.
  uint histBase = sg * SORT_RADIX;
  for (uint k = 0; k < KPT; ++k) {
    bool valid = slotValid(k);
    uint d = valid ? digitOf(tileKeys[k]) : 0u;
#ifdef RL_RANK_PARTITIONED
    // The lanes holding the same digit, in one instruction; invalid lanes are a class of their own (SORT_RADIX is
    // no digit), as the ballots below leave them out of every valid lane's peers. One instruction is not one
    // cycle: on an H100 this scatter took 16% longer than the ballots' on uniform keys (up to 32 distinct digits
    // a subgroup) and 5% less on few-valued ones (docs/results/partition-rank). Handing each digit's running
    // count from its lowest lane by a shuffle (one subgroup barrier a key, not two) won back only 1-2%.
    uvec4 peers = subgroupPartitionNV(valid ? d : uint(SORT_RADIX));
#else
    uvec4 peers = subgroupBallot(valid);
    for (uint b = 0; b < SORT_RADIX_BITS; ++b) {
      bool bit = ((d >> b) & 1u) != 0u;
      uvec4 votes = subgroupBallot(bit);
      peers &= bit ? votes : ~votes;
    }
#endif
    uint below = subgroupBallotExclusiveBitCount(peers);
    uint before = valid ? sMem[histBase + d] : 0u;
    // Every peer reads the running count before the lowest peer advances it.
    subgroupMemoryBarrierShared();
    subgroupBarrier();
    if (valid && below == 0u) sMem[histBase + d] = before + subgroupBallotBitCount(peers);
    subgroupMemoryBarrierShared();
    subgroupBarrier();
    tilePlace[k] = before + below;
  }
  barrier();

  // Column scan: counts per (subgroup, digit) become the start of the subgroup's run within the digit.
  uint mine = 0;
  for (uint k = 0; k < DIGITS_PER_THREAD; ++k) {
    uint d = firstOwnedDigit() + k;
    uint run = 0;
    for (uint s = 0; s < NUM_SG; ++s) {
      uint c = sMem[s * SORT_RADIX + d];
      sMem[s * SORT_RADIX + d] = run;
      run += c;
    }
    tileDigitCount[k] = run;
    mine += run;
  }
  uint unused;
  uint localStart = groupExclusiveAdd(mine, unused);
  for (uint k = 0; k < DIGITS_PER_THREAD; ++k) {
    sLocalStart[firstOwnedDigit() + k] = localStart;
    localStart += tileDigitCount[k];
  }
  barrier();
  return true;
}

// Exclusive scan over digits of per-digit totals (each invocation passes its owned digits' totals in
// `totals`); returns, in `starts`, where each owned digit begins in the whole output.
void digitStarts(uint totals[DIGITS_PER_THREAD], out uint starts[DIGITS_PER_THREAD]) {
  uint mine = 0;
  for (uint k = 0; k < DIGITS_PER_THREAD; ++k) mine += totals[k];
  uint unused;
  uint start = groupExclusiveAdd(mine, unused);
  for (uint k = 0; k < DIGITS_PER_THREAD; ++k) {
    starts[k] = start;
    start += totals[k];
  }
}

// Call after sGlobalShift is set for every digit (by its owner; the barriers in here order it).
void tileScatter() {
  uint t = gl_LocalInvocationID.x;
  uint lane = gl_SubgroupInvocationID;
  uint histBase = gl_SubgroupID * SORT_RADIX;
  uint values[KPT];
  for (uint k = 0; k < KPT; ++k) {
    if (slotValid(k)) {
      values[k] = pc.valuesIn.v[sliceBegin + k * SG_SIZE + lane];
      uint d = digitOf(tileKeys[k]);
      tilePlace[k] += sLocalStart[d] + sMem[histBase + d];
    }
  }
  barrier();  // every place computed before the histograms are overwritten by the tile

  for (uint k = 0; k < KPT; ++k) {
    if (slotValid(k)) {
      sMem[tilePlace[k]] = tileKeys[k];
      sMem[TILE + tilePlace[k]] = values[k];
    }
  }
  barrier();
  uint tileCount = min(TILE, tileLimit - tileBegin);
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

#endif
