// Random numbers whose stream is a function of (path id, frame, bounce, seed) only, never of the thread
// index: reordering paths between bounces therefore changes no sample (the project's central invariant).
#ifndef RAYLAB_RNG_GLSL
#define RAYLAB_RNG_GLSL

// PCG hash (Jarzynski & Olano 2020): a good 32-bit mixer in a handful of instructions.
uint pcgHash(uint v) {
  uint state = v * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

// `stream` separates independent uses within one bounce (RL_RNG_* in shared_types.h).
uint rngSeed(uint pathId, uint frame, uint bounce, uint seed, uint stream) {
  return pcgHash(pathId ^ pcgHash(frame ^ pcgHash(bounce * 16u + stream ^ pcgHash(seed))));
}

// Uniform float in [0, 1) from the top 24 bits; advances the state.
float rngNext(inout uint state) {
  state = state * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  word = (word >> 22u) ^ word;
  return float(word >> 8) * (1.0 / 16777216.0);
}

#endif
