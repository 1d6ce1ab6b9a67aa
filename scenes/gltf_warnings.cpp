#include "scenes/gltf_warnings.h"

#include <tiny_gltf.h>

#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace raylab::gltf {
namespace {

constexpr const char* kNotFound = "File not found : ";  // tinygltf's words for an absent external file
constexpr const char* kNoImage = "Failed to load external 'uri' for image[";  // its follow-up, by index
constexpr size_t kShown = 3;                             // names or lines shown before "and N more"

std::string baseName(const std::string& path) {
  size_t slash = path.find_last_of("/\\");
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// The image's index for an absent file tinygltf names (it may have joined the glTF's folder), or -1.
int imageNamed(const tinygltf::Model& model, const std::string& file) {
  for (size_t i = 0; i < model.images.size(); ++i) {
    const std::string& uri = model.images[i].uri;
    if (!uri.empty() && (uri == file || baseName(uri) == baseName(file))) return static_cast<int>(i);
  }
  return -1;
}

std::string someOf(const std::vector<std::string>& names) {
  std::string out;
  for (size_t i = 0; i < names.size() && i < kShown; ++i) out += (i ? ", " : "") + names[i];
  if (names.size() > kShown) out += " and " + std::to_string(names.size() - kShown) + " more";
  return out;
}

}  // namespace

std::set<int> imagesUsedByMaterials(const tinygltf::Model& model) {
  std::set<int> used;
  auto add = [&](int texture) {
    if (texture >= 0 && static_cast<size_t>(texture) < model.textures.size() &&
        model.textures[static_cast<size_t>(texture)].source >= 0)
      used.insert(model.textures[static_cast<size_t>(texture)].source);
  };
  for (const tinygltf::Material& m : model.materials) {
    add(m.pbrMetallicRoughness.baseColorTexture.index);
    bool emissive = false;
    for (double c : m.emissiveFactor) emissive = emissive || c > 0.0;
    if (emissive) add(m.emissiveTexture.index);
  }
  return used;
}

std::vector<std::string> summariseLoadWarnings(const std::string& warnings, const tinygltf::Model& model) {
  const std::set<int> used = imagesUsedByMaterials(model);
  std::vector<std::string> missingUsed, missingUnused, others;
  std::istringstream lines(warnings);
  for (std::string line; std::getline(lines, line);) {
    if (line.empty()) continue;
    if (line.rfind(kNoImage, 0) == 0) {
      // The same absent file again, by image index: said once above when no material uses it.
      const int image = std::atoi(line.c_str() + std::string(kNoImage).size());
      if (!used.count(image)) continue;
    }
    if (line.rfind(kNotFound, 0) != 0) {
      others.push_back(line);
      continue;
    }
    const std::string file = line.substr(std::string(kNotFound).size());
    const int image = imageNamed(model, file);
    // A file that is no image (a buffer) or an image a material reads: it matters, named in full.
    if (image < 0 || used.count(image)) missingUsed.push_back(baseName(file));
    else missingUnused.push_back(baseName(file));
  }
  std::vector<std::string> out;
  if (!missingUsed.empty())
    out.push_back(std::to_string(missingUsed.size()) + " file(s) not found that the scene uses (drawn untextured): " +
                  someOf(missingUsed));
  if (!missingUnused.empty())
    out.push_back(std::to_string(missingUnused.size()) +
                  " image file(s) not found that no material the lab reads uses (nothing lost): " + someOf(missingUnused));
  for (size_t i = 0; i < others.size() && i < kShown; ++i) out.push_back(others[i]);
  if (others.size() > kShown) out.push_back("... and " + std::to_string(others.size() - kShown) + " more warnings from tinygltf");
  return out;
}

void printLoadWarnings(const std::string& file, const std::string& warnings, const tinygltf::Model& model) {
  for (const std::string& line : summariseLoadWarnings(warnings, model))
    std::fprintf(stderr, "warning: %s: %s\n", file.c_str(), line.c_str());
}

}  // namespace raylab::gltf
