#include "scenes/scene_library.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <stdexcept>

#include "scenes/gltf_loader.h"
#include "scenes/procedural.h"

namespace raylab {

namespace {

bool endsWithNoCase(const std::string& s, const std::string& suffix) {
  if (s.size() < suffix.size()) return false;
  return std::equal(
      suffix.begin(), suffix.end(), s.end() - static_cast<std::ptrdiff_t>(suffix.size()), [](char a, char b) {
        return std::tolower(static_cast<unsigned char>(a)) == std::tolower(static_cast<unsigned char>(b));
      });
}

}  // namespace

std::vector<std::string> builtinSceneNames() { return {"temple", "cornell", "furnace"}; }

Scene loadSceneByName(const std::string& nameOrPath) {
  if (nameOrPath == "temple") return makeTemple();
  if (nameOrPath == "cornell") return makeCornell();
  if (nameOrPath == "furnace") return makeFurnace();
  if (endsWithNoCase(nameOrPath, ".gltf") || endsWithNoCase(nameOrPath, ".glb")) {
    // Checked here so the message is the same for both formats and does not depend on tinygltf's.
    std::error_code ec;
    if (!std::filesystem::is_regular_file(nameOrPath, ec))
      throw SceneLoadError(nameOrPath + ": file not found");
    return loadGltf(nameOrPath);
  }
  std::string names;
  for (const std::string& n : builtinSceneNames()) names += n + ", ";
  throw std::invalid_argument("unknown scene '" + nameOrPath + "': expected one of " + names +
                              "or a path to a .gltf or .glb file");
}

}  // namespace raylab
