#include "renderer/png_writer.h"

#include <stdexcept>

#include <stb_image_write.h>

namespace raylab {

void writePng(const std::string& path, uint32_t width, uint32_t height, const std::vector<uint32_t>& rgba) {
  if (rgba.size() < static_cast<size_t>(width) * height) throw std::runtime_error(path + ": image too small");
  if (!stbi_write_png(path.c_str(), static_cast<int>(width), static_cast<int>(height), 4, rgba.data(),
                      static_cast<int>(width * 4)))
    throw std::runtime_error("cannot write " + path);
}

}  // namespace raylab
