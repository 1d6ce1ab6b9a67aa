// Pieces of the glTF loader shared by its source files (not a public API: include gltf_loader.h).
// Every function here validates indices and byte ranges itself and reports a problem through
// Source::fail, which names the file, so no caller ever touches memory tinygltf did not check.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "scenes/scene.h"

namespace tinygltf {
class Model;
struct Image;
}  // namespace tinygltf

namespace raylab::gltf {

// The model being converted and the file it came from (for messages).
struct Source {
  const tinygltf::Model& model;
  std::string file;

  // Throws SceneLoadError("<file>: <message>").
  [[noreturn]] void fail(const std::string& message) const;
  // Prints "warning: <file>: <message>" to stderr and keeps the message in `warnings` (the scene carries
  // them to the window's scene panel): for parts that are skipped, not wrong.
  void warn(const std::string& message) const;
  mutable std::vector<std::string> warnings;
};

// "what" names the accessor's use for messages, e.g. "POSITION of mesh 'x' primitive 0".
// POSITION: VEC3 FLOAT, every value finite.
std::vector<glm::vec3> readPositions(const Source& src, int accessor, const std::string& what);
// TEXCOORD_0: VEC2 FLOAT, or normalized UNSIGNED_BYTE / UNSIGNED_SHORT; every value finite.
std::vector<glm::vec2> readTexcoords(const Source& src, int accessor, const std::string& what);
// Indices: SCALAR UNSIGNED_BYTE / UNSIGNED_SHORT / UNSIGNED_INT (range against vertices: caller).
std::vector<uint32_t> readIndices(const Source& src, int accessor, const std::string& what);

// Appends one Material per glTF material, in order (so glTF material i is scene material
// `first + i`), and the textures they use. Images are decoded here, not by tinygltf (see
// storeEncodedImage), and only those a material uses; an image that is absent or cannot be decoded
// means "no texture", with a warning, as a renderer can still draw the surface.
void convertMaterials(const Source& src, Scene& scene);

// tinygltf image callback: keeps the encoded bytes instead of decoding every image during parsing.
// Decoding then happens only for images a material uses, and an undecodable alternate image (for
// example Sponza's optional .dds files) cannot make the whole load fail.
bool storeEncodedImage(tinygltf::Image* image, int imageIndex, std::string* err, std::string* warn,
                       int reqWidth, int reqHeight, const unsigned char* bytes, int size, void* user);

}  // namespace raylab::gltf
