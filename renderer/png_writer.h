// PNG output through stb_image_write (Debian's libstb).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace raylab {

// Writes RGBA8 pixels (R in the low byte) as a PNG through writeFileChecked (renderer/checked_write.h): all of
// it or nothing under `path`. Throws WriteError (a std::runtime_error) naming the path and the reason.
void writePng(const std::string& path, uint32_t width, uint32_t height, const std::vector<uint32_t>& rgba);

}  // namespace raylab
