// glTF loader (scenes/gltf_loader.h): any bytes as a .glb (when they start with the binary magic "glTF")
// or a .gltf (JSON text) file. The only acceptable failure is SceneLoadError, with a message.
#include <cstring>

#include "scenes/gltf_loader.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
  std::string path = raylab::fuzz::writeInput(data, size, binary ? ".glb" : ".gltf");
  try {
    raylab::loadGltf(path);
  } catch (const raylab::SceneLoadError& e) {
    if (std::strlen(e.what()) == 0) __builtin_trap();  // an error must say what is wrong
  }
  return 0;
}
