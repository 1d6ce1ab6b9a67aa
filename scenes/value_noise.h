// Smooth value noise for displacing procedural geometry: a hash of the integer lattice around a point,
// interpolated with a smoothstep. Integer arithmetic and a fixed formula make it the same on every platform,
// so displaced scenes are as deterministic as their seed.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

namespace raylab {

// A well-mixed 32-bit hash of a lattice point and a seed.
uint32_t latticeHash(const glm::ivec3& p, uint32_t seed);
// latticeHash mapped to [0, 1).
float latticeRandom(const glm::ivec3& p, uint32_t seed);
// Value noise in [-1, 1], smooth across lattice cells of size 1.
float valueNoise(const glm::vec3& p, uint32_t seed);

}  // namespace raylab
