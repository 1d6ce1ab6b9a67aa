// Image sizes known by name, the real-time renderers' frames at one sample (issue 36): `--size 720p`, the
// bench's `--sizes 720p,1080p`, the CSV's size_name column and the paths chart's marks all read them here.
#pragma once

#include <cstdint>
#include <string_view>

namespace raylab {

struct NamedSize {
  const char* name;
  uint32_t width, height;
};

inline constexpr NamedSize kNamedSizes[] = {
    {"720p", 1280, 720},
    {"1080p", 1920, 1080},
};

// The size called `name`, or nullptr.
constexpr const NamedSize* findNamedSize(std::string_view name) {
  for (const NamedSize& s : kNamedSizes)
    if (name == s.name) return &s;
  return nullptr;
}

// The name of width x height, or nullptr where it has none.
constexpr const NamedSize* namedSizeOf(uint32_t width, uint32_t height) {
  for (const NamedSize& s : kNamedSizes)
    if (s.width == width && s.height == height) return &s;
  return nullptr;
}

}  // namespace raylab
