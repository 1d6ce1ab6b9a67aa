#include "scenes/value_noise.h"

#include <cmath>

namespace raylab {

uint32_t latticeHash(const glm::ivec3& p, uint32_t seed) {
  // Each coordinate folded in by a multiply and an xorshift (the "lowbias32" finaliser between steps).
  uint32_t h = seed * 0x9E3779B9u + 0x7F4A7C15u;
  for (int a = 0; a < 3; ++a) {
    h ^= static_cast<uint32_t>(p[a]) * 0x85EBCA6Bu;
    h ^= h >> 16;
    h *= 0x7FEB352Du;
    h ^= h >> 15;
    h *= 0x846CA68Bu;
    h ^= h >> 16;
  }
  return h;
}

float latticeRandom(const glm::ivec3& p, uint32_t seed) {
  return static_cast<float>(latticeHash(p, seed) >> 8) * (1.0f / 16777216.0f);
}

float valueNoise(const glm::vec3& p, uint32_t seed) {
  glm::vec3 cell = glm::floor(p);
  glm::ivec3 i(cell);
  glm::vec3 f = p - cell;
  glm::vec3 w = f * f * (3.0f - 2.0f * f);
  float corners[2][2][2];
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 2; ++x) corners[z][y][x] = latticeRandom(i + glm::ivec3(x, y, z), seed);
  auto lerp = [](float a, float b, float t) { return a + (b - a) * t; };
  float y0 = lerp(lerp(corners[0][0][0], corners[0][0][1], w.x), lerp(corners[0][1][0], corners[0][1][1], w.x), w.y);
  float y1 = lerp(lerp(corners[1][0][0], corners[1][0][1], w.x), lerp(corners[1][1][0], corners[1][1][1], w.x), w.y);
  return 2.0f * lerp(y0, y1, w.z) - 1.0f;
}

}  // namespace raylab
