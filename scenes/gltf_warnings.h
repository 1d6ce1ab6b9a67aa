// tinygltf's load warnings, told apart before they are printed: an image file it could not find matters
// only if a material the loader converts reads that image (gltf_materials.cpp: base colour textures, and
// emissive textures of emissive materials). Sponza lists two dozen MSFT_texture_dds .dds alternatives that
// no material of ours uses; saying "File not found ... and 99 more" left open whether anything was lost.
#pragma once

#include <set>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
}

namespace raylab::gltf {

// The image indices behind the textures that convertMaterials reads.
std::set<int> imagesUsedByMaterials(const tinygltf::Model& model);

// The lines to print for `warnings` (tinygltf's, one per line): absent image files split into those a
// material uses (named, drawn untextured) and those none uses (counted, a few named); other warnings, a
// few lines and a count.
std::vector<std::string> summariseLoadWarnings(const std::string& warnings, const tinygltf::Model& model);

// Prints summariseLoadWarnings as "warning: <file>: <line>" to stderr.
void printLoadWarnings(const std::string& file, const std::string& warnings, const tinygltf::Model& model);

}  // namespace raylab::gltf
