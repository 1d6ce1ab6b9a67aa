// glTF 2.0 (.gltf with external or embedded buffers, .glb) to the flat Scene model, through tinygltf.
// tinygltf parses and decodes, but accepts many invalid files (out-of-range indices, accessors that
// read past their buffers, node cycles), so every index and byte range is validated here before any
// memory is read; a file that fails throws SceneLoadError naming the file and the offending object.
#pragma once

#include <string>

#include "scenes/scene.h"

namespace raylab {

// Flattens the default scene's node hierarchy (triangle primitives only, TEXCOORD_0 and the base
// colour texture kept), one Viewpoint per perspective camera node, then a "default" viewpoint that
// frames the scene bounds. Scene::name is the file stem, skyColor white.
Scene loadGltf(const std::string& path);

}  // namespace raylab
