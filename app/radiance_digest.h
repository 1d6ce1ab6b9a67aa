// A digest of a frame's accumulated radiance (`raylab render --frame-digests`): FNV-1a over the floats' bits,
// so two renders can be compared frame by frame, bit for bit (the invariant: any key strategy and sort give
// the unsorted frame), without writing every image. Equal images give equal digests; a digest is no
// checksum against tampering, only a cheap identity for tests.
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace raylab {

inline std::string radianceDigest(const std::vector<glm::vec3>& radiance) {
  uint64_t h = 1469598103934665603ull;  // FNV-1a 64-bit offset basis
  const auto* bytes = reinterpret_cast<const unsigned char*>(radiance.data());
  for (size_t i = 0; i < radiance.size() * sizeof(glm::vec3); ++i) h = (h ^ bytes[i]) * 1099511628211ull;
  char text[17];
  std::snprintf(text, sizeof(text), "%016llx", static_cast<unsigned long long>(h));
  return text;
}

}  // namespace raylab
