#include "renderer/png_writer.h"

#include <stdexcept>

#include <stb_image_write.h>

#include "renderer/checked_write.h"

namespace raylab {
namespace {

// stb's callback: the encoded bytes are gathered in memory and written once, checked (writeFileChecked).
void appendBytes(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<size_t>(size));
}

}  // namespace

void writePng(const std::string& path, uint32_t width, uint32_t height, const std::vector<uint32_t>& rgba) {
  if (rgba.size() < static_cast<size_t>(width) * height) throw std::runtime_error(path + ": image too small");
  std::string png;
  if (!stbi_write_png_to_func(appendBytes, &png, static_cast<int>(width), static_cast<int>(height), 4, rgba.data(),
                              static_cast<int>(width * 4)))
    throw std::runtime_error("cannot encode " + path + " as PNG");
  writeFileChecked(path, png);
}

}  // namespace raylab
