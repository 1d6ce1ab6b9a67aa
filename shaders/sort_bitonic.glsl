// Shared pieces of the bitonic sort shaders. The network is the all-ascending form (a "flip" step that
// compares p with k-1-p inside each block of k, then half-cleaners comparing i with i+d): every comparator
// puts the smaller key at the lower index. A count that is not a power of two is padded virtually with
// +infinity at the end; such padding never moves in this form (its partner is always at a lower index and
// no larger), so a comparator whose upper index is past the end is skipped and nothing is stored for it.
#ifndef RAYLAB_SORT_BITONIC_GLSL
#define RAYLAB_SORT_BITONIC_GLSL

// Indices (i < j) of comparator c of a flip step with blocks of 2^blockLog.
uvec2 bitonicFlipPair(uint c, uint blockLog) {
  uint halfLog = blockLog - 1u;
  uint blockStart = (c >> halfLog) << blockLog;
  uint p = c & ((1u << halfLog) - 1u);
  return uvec2(blockStart + p, blockStart + (1u << blockLog) - 1u - p);
}

// Indices (i < j = i + 2^distanceLog) of comparator c of a half-cleaner step.
uvec2 bitonicHalfPair(uint c, uint distanceLog) {
  uint i = ((c >> distanceLog) << (distanceLog + 1u)) + (c & ((1u << distanceLog) - 1u));
  return uvec2(i, i + (1u << distanceLog));
}

#endif
