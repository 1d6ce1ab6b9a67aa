// One entry point from a scene name on the command line (or in Settings) to a Scene: the built-in
// procedural scenes by name, glTF files by path.
#pragma once

#include <string>
#include <vector>

#include "scenes/scene.h"

namespace raylab {

// "temple", "cornell", "furnace" (default parameters), or a path ending in .gltf / .glb (any case).
// Throws SceneLoadError for a file that is missing or unusable, std::invalid_argument for any other
// name (the message lists the accepted names; the CLI turns it into a usage error).
Scene loadSceneByName(const std::string& nameOrPath);

// The names loadSceneByName accepts besides file paths, default scene first.
std::vector<std::string> builtinSceneNames();

}  // namespace raylab
