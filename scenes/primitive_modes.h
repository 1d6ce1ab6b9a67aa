// glTF primitive modes (glTF 2.0, 3.7.2.1) turned into triangle lists. Strips and fans are expanded with
// the specification's vertex order per triangle, so each triangle keeps the winding the file gives it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace raylab {

enum GltfMode : int {
  kModePoints = 0,
  kModeLines = 1,
  kModeLineLoop = 2,
  kModeLineStrip = 3,
  kModeTriangles = 4,
  kModeTriangleStrip = 5,
  kModeTriangleFan = 6,
};

// "POINTS", "TRIANGLE_FAN", ...; empty for a number that is no glTF mode.
std::string primitiveModeName(int mode);
bool isTriangleMode(int mode);

// Three indices per triangle from `indices` (the primitive's index accessor, or 0..n-1 without one) drawn
// in triangle `mode`:
//   TRIANGLES       (v[3i], v[3i+1], v[3i+2]); leftover indices are ignored
//   TRIANGLE_STRIP  p_i = (v[i], v[i + 1 + i%2], v[i + 2 - i%2])   (every other triangle flipped back)
//   TRIANGLE_FAN    p_i = (v[i + 1], v[i + 2], v[0])
// Strip and fan triangles that repeat an index are dropped: they have no area (strips use them to join).
std::vector<uint32_t> triangleListIndices(int mode, const std::vector<uint32_t>& indices);

}  // namespace raylab
