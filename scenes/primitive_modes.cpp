#include "scenes/primitive_modes.h"

namespace raylab {

std::string primitiveModeName(int mode) {
  static const char* const kNames[] = {"POINTS",    "LINES",          "LINE_LOOP",   "LINE_STRIP",
                                       "TRIANGLES", "TRIANGLE_STRIP", "TRIANGLE_FAN"};
  return mode >= 0 && mode <= kModeTriangleFan ? kNames[mode] : "";
}

bool isTriangleMode(int mode) {
  return mode == kModeTriangles || mode == kModeTriangleStrip || mode == kModeTriangleFan;
}

std::vector<uint32_t> triangleListIndices(int mode, const std::vector<uint32_t>& v) {
  std::vector<uint32_t> out;
  if (mode == kModeTriangles) {
    out.assign(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() - v.size() % 3));
    return out;
  }
  if (!isTriangleMode(mode) || v.size() < 3) return out;
  const size_t n = v.size() - 2;
  out.reserve(3 * n);
  for (size_t i = 0; i < n; ++i) {
    uint32_t a, b, c;
    if (mode == kModeTriangleStrip) {
      a = v[i], b = v[i + 1 + i % 2], c = v[i + 2 - i % 2];
    } else {
      a = v[i + 1], b = v[i + 2], c = v[0];
    }
    if (a == b || b == c || a == c) continue;
    out.insert(out.end(), {a, b, c});
  }
  return out;
}

}  // namespace raylab
