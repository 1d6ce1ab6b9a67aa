// One entry point from a scene name on the command line (or in Settings) to a Scene: the built-in
// procedural scenes by name, glTF files by path.
#pragma once

#include <string>
#include <vector>

#include "scenes/clutter.h"
#include "scenes/scene.h"

namespace raylab {

// "temple", "cornell", "furnace" (default parameters), "temple-detail:N" (scenes/temple_detail.h), or a
// path ending in .gltf / .glb (any case). Throws SceneLoadError for a file that is missing or unusable,
// std::invalid_argument for any other name or a bad size (the message lists the accepted names and
// ranges; the CLI turns it into a usage error).
// `clutterSeed` lays out the cluttered room (scenes/clutter.h).
Scene loadSceneByName(const std::string& nameOrPath, uint32_t clutterSeed = kClutterDefaultSeed);

// What loadSceneByName checks before building or reading anything (the name and a family's size, not
// whether a file exists), for plans that name many scenes: throws its std::invalid_argument.
void checkSceneName(const std::string& nameOrPath);

// Names of the built-in scenes for a scene picker, default scene first; the family temple-detail appears
// at one size (any other size can be typed as a name).
std::vector<std::string> builtinSceneNames();

}  // namespace raylab
