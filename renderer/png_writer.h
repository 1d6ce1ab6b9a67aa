// PNG output through stb_image_write (Debian's libstb).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace raylab {

// Writes RGBA8 pixels (R in the low byte) as a PNG; throws std::runtime_error naming the path on failure.
void writePng(const std::string& path, uint32_t width, uint32_t height, const std::vector<uint32_t>& rgba);

}  // namespace raylab
