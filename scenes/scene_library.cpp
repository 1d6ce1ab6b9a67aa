#include "scenes/scene_library.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iterator>
#include <stdexcept>

#include "scenes/clutter.h"
#include "scenes/gltf_loader.h"
#include "scenes/procedural.h"
#include "scenes/temple_detail.h"

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

// The procedural scenes that take no parameter.
const char* const kFixedScenes[] = {"temple", "cornell", "furnace"};

std::vector<std::string> builtinSceneNames() {
  std::vector<std::string> names(std::begin(kFixedScenes), std::end(kFixedScenes));
  names.push_back(std::string(kTempleDetailName) + ":1e5");
  names.push_back(std::string(kClutterName) + ":2e5");
  return names;
}

void checkSceneName(const std::string& nameOrPath) {
  if (std::find(std::begin(kFixedScenes), std::end(kFixedScenes), nameOrPath) != std::end(kFixedScenes)) return;
  if (isTempleDetailName(nameOrPath)) {
    parseTempleDetailTriangles(nameOrPath);
    return;
  }
  if (isClutterName(nameOrPath)) {
    parseClutterTriangles(nameOrPath);
    return;
  }
  if (endsWithNoCase(nameOrPath, ".gltf") || endsWithNoCase(nameOrPath, ".glb")) return;
  std::string names;
  for (const char* n : kFixedScenes) names += std::string(n) + ", ";
  throw std::invalid_argument("unknown scene '" + nameOrPath + "': expected one of " + names + kTempleDetailName +
                              ":N (N triangles, 1e4 to 3e7), " + kClutterName +
                              ":N (5e4 to 3e6), or a path to a .gltf or .glb file");
}

Scene loadSceneByName(const std::string& nameOrPath, uint32_t clutterSeed) {
  checkSceneName(nameOrPath);
  if (nameOrPath == "temple") return makeTemple();
  if (nameOrPath == "cornell") return makeCornell();
  if (nameOrPath == "furnace") return makeFurnace();
  if (isTempleDetailName(nameOrPath)) return makeTempleDetail(parseTempleDetailTriangles(nameOrPath));
  if (isClutterName(nameOrPath)) return makeClutter(parseClutterTriangles(nameOrPath), clutterSeed);
  // A glTF file. Checked here so the message is the same for both formats and does not depend on tinygltf's.
  std::error_code ec;
  if (!std::filesystem::is_regular_file(nameOrPath, ec)) throw SceneLoadError(nameOrPath + ": file not found");
  return loadGltf(nameOrPath);
}

}  // namespace raylab
