// glTF file to Scene: tinygltf parses, then this file walks the default scene's node hierarchy,
// instancing each mesh's triangles under its node's world transform and turning camera nodes into
// viewpoints. All indices into the model are checked here (tinygltf does not), see gltf_internal.h.
#include "scenes/gltf_loader.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <optional>
#include <set>
#include <sstream>

#include "scenes/gltf_internal.h"
#include "scenes/gltf_warnings.h"
#include "scenes/primitive_modes.h"

namespace raylab {

namespace {

using gltf::Source;

// Limits that only a hostile or broken file reaches (a node DAG can instance a mesh exponentially
// often); they turn an out-of-memory crash into a SceneLoadError. 20M triangles are about 1.3 GB.
constexpr size_t kMaxTriangles = 20'000'000;
constexpr size_t kMaxNodeVisits = 1'000'000;

std::string lowercase(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

bool allFinite(const std::vector<double>& values) {
  return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

class Converter {
 public:
  Converter(const tinygltf::Model& model, const std::string& file) : src_{model, file} {}

  Scene run(const std::string& name) {
    const tinygltf::Model& m = src_.model;
    gltf::convertMaterials(src_, scene_);  // glTF material i becomes scene material i
    checkNodes();
    meshCache_.resize(m.meshes.size());
    traverse(rootNodes());
    if (scene_.triangles.empty()) {
      std::string skipped;
      for (const std::string& mode : skippedModes_) skipped += (skipped.empty() ? "" : ", ") + mode;
      src_.fail("the scene has no triangles to render" +
                (skipped.empty() ? std::string()
                                 : " (its primitives are " + skipped +
                                       "; only TRIANGLES, TRIANGLE_STRIP and TRIANGLE_FAN have a surface)"));
    }
    scene_.loadWarnings = src_.warnings;
    addDefaultViewpoint();
    scene_.name = name;
    scene_.skyColor = glm::vec3(1.0f);  // glTF scenes are lit by a white sky unless they emit
    return std::move(scene_);
  }

 private:
  std::string nodeLabel(size_t i) const {
    const std::string& n = src_.model.nodes[i].name;
    return "node " + std::to_string(i) + (n.empty() ? "" : " '" + n + "'");
  }

  // Every node's references and transform, once, before any traversal relies on them.
  void checkNodes() const {
    const tinygltf::Model& m = src_.model;
    for (size_t i = 0; i < m.nodes.size(); ++i) {
      const tinygltf::Node& n = m.nodes[i];
      for (int c : n.children)
        if (c < 0 || static_cast<size_t>(c) >= m.nodes.size())
          src_.fail(nodeLabel(i) + ": child " + std::to_string(c) + " out of range (file has " +
                    std::to_string(m.nodes.size()) + " nodes)");
      if (n.mesh >= 0 && static_cast<size_t>(n.mesh) >= m.meshes.size())
        src_.fail(nodeLabel(i) + ": mesh " + std::to_string(n.mesh) + " out of range (file has " +
                  std::to_string(m.meshes.size()) + ")");
      if (n.camera >= 0 && static_cast<size_t>(n.camera) >= m.cameras.size())
        src_.fail(nodeLabel(i) + ": camera " + std::to_string(n.camera) + " out of range (file has " +
                  std::to_string(m.cameras.size()) + ")");
      bool shapes = (n.matrix.empty() || n.matrix.size() == 16) &&
                    (n.translation.empty() || n.translation.size() == 3) &&
                    (n.rotation.empty() || n.rotation.size() == 4) &&
                    (n.scale.empty() || n.scale.size() == 3);
      if (!shapes) src_.fail(nodeLabel(i) + ": matrix, translation, rotation or scale has the wrong length");
      if (!allFinite(n.matrix) || !allFinite(n.translation) || !allFinite(n.rotation) || !allFinite(n.scale))
        src_.fail(nodeLabel(i) + ": transform is not finite");
    }
  }

  // The default scene's roots; without scenes, every node that is nobody's child.
  std::vector<int> rootNodes() const {
    const tinygltf::Model& m = src_.model;
    if (m.defaultScene >= 0 && static_cast<size_t>(m.defaultScene) >= m.scenes.size())
      src_.fail("default scene " + std::to_string(m.defaultScene) + " out of range (file has " +
                std::to_string(m.scenes.size()) + " scenes)");
    if (!m.scenes.empty()) {
      size_t s = m.defaultScene >= 0 ? static_cast<size_t>(m.defaultScene) : 0;
      for (int r : m.scenes[s].nodes)
        if (r < 0 || static_cast<size_t>(r) >= m.nodes.size())
          src_.fail("scene " + std::to_string(s) + ": node " + std::to_string(r) +
                    " out of range (file has " + std::to_string(m.nodes.size()) + " nodes)");
      return m.scenes[s].nodes;
    }
    std::vector<char> isChild(m.nodes.size(), 0);
    for (const tinygltf::Node& n : m.nodes)
      for (int c : n.children) isChild[static_cast<size_t>(c)] = 1;
    std::vector<int> roots;
    for (size_t i = 0; i < m.nodes.size(); ++i)
      if (!isChild[i]) roots.push_back(static_cast<int>(i));
    if (roots.empty() && !m.nodes.empty()) src_.fail("node hierarchy has no root: its nodes form a cycle");
    return roots;
  }

  glm::dmat4 localTransform(const tinygltf::Node& n) const {
    if (n.matrix.size() == 16) return glm::make_mat4(n.matrix.data());  // column-major, as glTF
    glm::dmat4 t(1.0), r(1.0), s(1.0);
    if (n.translation.size() == 3) t = glm::translate(glm::dmat4(1.0), glm::make_vec3(n.translation.data()));
    if (n.rotation.size() == 4)  // glTF stores x, y, z, w
      r = glm::mat4_cast(
          glm::normalize(glm::dquat(n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2])));
    if (n.scale.size() == 3) s = glm::scale(glm::dmat4(1.0), glm::make_vec3(n.scale.data()));
    return t * r * s;
  }

  // Depth-first with an explicit stack (a deep chain of nodes must not overflow the call stack).
  // A node met again while it is still on the current path is a cycle; a node reached through two
  // different parents is only shared (invalid glTF but harmless) and is instanced twice.
  void traverse(const std::vector<int>& roots) {
    struct Item {
      int node;
      glm::dmat4 parent;
      bool leaving;
    };
    const tinygltf::Model& m = src_.model;
    std::vector<char> onPath(m.nodes.size(), 0);
    std::vector<Item> stack;
    for (auto r = roots.rbegin(); r != roots.rend(); ++r) stack.push_back({*r, glm::dmat4(1.0), false});
    size_t visits = 0;
    while (!stack.empty()) {
      Item item = stack.back();
      stack.pop_back();
      size_t i = static_cast<size_t>(item.node);
      if (item.leaving) {
        onPath[i] = 0;
        continue;
      }
      if (onPath[i]) src_.fail(nodeLabel(i) + ": cycle in the node hierarchy (the node is its own ancestor)");
      if (++visits > kMaxNodeVisits)
        src_.fail("node hierarchy expands to more than 1,000,000 node instances");
      onPath[i] = 1;
      stack.push_back({item.node, glm::dmat4(1.0), true});
      const tinygltf::Node& n = m.nodes[i];
      glm::dmat4 world = item.parent * localTransform(n);
      if (n.mesh >= 0) instance(n.mesh, world, i);
      if (n.camera >= 0) addCamera(i, world);
      for (auto c = n.children.rbegin(); c != n.children.rend(); ++c) stack.push_back({*c, world, false});
    }
  }

  void instance(int mesh, const glm::dmat4& world, size_t node) {
    const std::vector<Triangle>& local = meshTriangles(mesh);
    if (scene_.triangles.size() + local.size() > kMaxTriangles)
      src_.fail("more than 20,000,000 triangles after instancing");
    bool mirrored = glm::determinant(world) < 0.0;  // keeps the winding (front faces) of mirrored copies
    for (Triangle t : local) {
      for (glm::vec3& v : t.v) {
        v = glm::vec3(world * glm::dvec4(v, 1.0));
        if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
          src_.fail(nodeLabel(node) + ": world transform makes positions non-finite");
      }
      if (mirrored) {
        std::swap(t.v[1], t.v[2]);
        std::swap(t.uv[1], t.uv[2]);
      }
      scene_.triangles.push_back(t);
    }
  }

  // A mesh's triangles in its own space, converted once however many nodes instance it.
  const std::vector<Triangle>& meshTriangles(int meshIndex) {
    std::optional<std::vector<Triangle>>& cached = meshCache_[static_cast<size_t>(meshIndex)];
    if (cached) return *cached;
    cached.emplace();
    const tinygltf::Mesh& mesh = src_.model.meshes[static_cast<size_t>(meshIndex)];
    for (size_t p = 0; p < mesh.primitives.size(); ++p) {
      std::string what = "mesh " + (mesh.name.empty() ? std::to_string(meshIndex) : "'" + mesh.name + "'") +
                         " primitive " + std::to_string(p);
      convertPrimitive(mesh.primitives[p], what, *cached);
    }
    return *cached;
  }

  void convertPrimitive(const tinygltf::Primitive& prim, const std::string& what,
                        std::vector<Triangle>& out) {
    const tinygltf::Model& m = src_.model;
    int mode = prim.mode == -1 ? kModeTriangles : prim.mode;
    const std::string modeName = primitiveModeName(mode);
    if (modeName.empty()) src_.fail(what + ": mode " + std::to_string(mode) + " is not a glTF primitive mode (0..6)");
    if (!isTriangleMode(mode)) {  // points and lines have no surface to hit
      src_.warn(what + ": mode " + modeName + " (" + std::to_string(mode) + ") draws no triangles, skipped");
      skippedModes_.insert(modeName + " (" + std::to_string(mode) + ")");
      return;
    }
    auto position = prim.attributes.find("POSITION");
    if (position == prim.attributes.end()) {
      src_.warn(what + ": no POSITION attribute, skipped");
      return;
    }
    std::vector<glm::vec3> positions = gltf::readPositions(src_, position->second, "POSITION of " + what);
    std::vector<glm::vec2> uvs;
    auto texcoord = prim.attributes.find("TEXCOORD_0");
    if (texcoord != prim.attributes.end()) {
      uvs = gltf::readTexcoords(src_, texcoord->second, "TEXCOORD_0 of " + what);
      if (uvs.size() != positions.size())
        src_.fail("accessor " + std::to_string(texcoord->second) + " (TEXCOORD_0 of " + what +
                  "): " + std::to_string(uvs.size()) + " elements, but POSITION has " +
                  std::to_string(positions.size()));
    }
    std::vector<uint32_t> indices;
    if (prim.indices >= 0) {
      indices = gltf::readIndices(src_, prim.indices, "indices of " + what);
      for (size_t i = 0; i < indices.size(); ++i)
        if (indices[i] >= positions.size())
          src_.fail("accessor " + std::to_string(prim.indices) + " (indices of " + what + "): index " +
                    std::to_string(indices[i]) + " at position " + std::to_string(i) +
                    " out of range (POSITION has " + std::to_string(positions.size()) + " vertices)");
    } else {
      indices.resize(positions.size());
      for (size_t i = 0; i < indices.size(); ++i) indices[i] = static_cast<uint32_t>(i);
    }
    if (mode == kModeTriangles && indices.size() % 3 != 0)
      src_.warn(what + ": " + std::to_string(indices.size()) + " indices is not a multiple of 3, the last " +
                std::to_string(indices.size() % 3) + " ignored");
    uint32_t material;
    if (prim.material >= 0) {
      if (static_cast<size_t>(prim.material) >= m.materials.size())
        src_.fail(what + ": material " + std::to_string(prim.material) + " out of range (file has " +
                  std::to_string(m.materials.size()) + ")");
      material = static_cast<uint32_t>(prim.material);
    } else {
      material = defaultMaterial();
    }
    indices = triangleListIndices(mode, indices);
    for (size_t i = 0; i + 2 < indices.size(); i += 3) {
      Triangle t;
      for (int k = 0; k < 3; ++k) {
        t.v[k] = positions[indices[i + static_cast<size_t>(k)]];
        if (!uvs.empty()) t.uv[k] = uvs[indices[i + static_cast<size_t>(k)]];
      }
      t.material = material;
      out.push_back(t);
    }
  }

  // glTF's default material (white, metallic 1 in the spec) would render mirror-black under a
  // white sky; the lab's convention is a neutral grey diffuse instead.
  uint32_t defaultMaterial() {
    if (defaultMaterial_ < 0) {
      Material d;
      d.name = "default";
      d.baseColor = glm::vec3(0.8f);
      scene_.materials.push_back(d);
      defaultMaterial_ = static_cast<int>(scene_.materials.size() - 1);
    }
    return static_cast<uint32_t>(defaultMaterial_);
  }

  // The first candidate that is non-empty and not yet a viewpoint name ("default" is reserved for
  // the computed view), else the fallback with a number appended as needed.
  std::string uniqueName(const std::vector<std::string>& candidates, const std::string& fallback) const {
    auto taken = [&](const std::string& n) { return n == "default" || scene_.findViewpoint(n) != nullptr; };
    for (const std::string& c : candidates)
      if (!c.empty() && !taken(c)) return c;
    std::string name = fallback;
    for (int k = 2; taken(name); ++k) name = fallback + "_" + std::to_string(k);
    return name;
  }

  void addCamera(size_t node, const glm::dmat4& world) {
    const tinygltf::Model& m = src_.model;
    int index = m.nodes[node].camera;
    const tinygltf::Camera& cam = m.cameras[static_cast<size_t>(index)];
    std::string label = "camera " + std::to_string(index) + (cam.name.empty() ? "" : " '" + cam.name + "'");
    if (cam.type != "perspective") {
      src_.warn(label + ": type '" + cam.type + "' is not supported, no viewpoint");
      return;
    }
    double yfov = cam.perspective.yfov;
    if (!(yfov > 0.0 && yfov < 3.14159))
      src_.fail(label + ": yfov " + std::to_string(yfov) + " is not in (0, pi)");
    glm::dvec3 position(world * glm::dvec4(0, 0, 0, 1));
    glm::dvec3 forward = glm::dmat3(world) * glm::dvec3(0, 0, -1);  // glTF cameras look down -Z
    glm::dvec3 up = glm::dmat3(world) * glm::dvec3(0, 1, 0);
    if (!(glm::length(forward) > 1e-12) || !(glm::length(up) > 1e-12) ||
        glm::length(glm::cross(forward, up)) < 1e-9 * glm::length(forward) * glm::length(up))
      src_.fail(nodeLabel(node) + ": " + label + " has a degenerate orientation");
    Viewpoint v;
    v.name = uniqueName({cam.name, m.nodes[node].name}, "camera" + std::to_string(index));
    v.position = glm::vec3(position);
    v.target = glm::vec3(position + glm::normalize(forward));
    v.up = glm::vec3(glm::normalize(up));
    v.yfovRadians = static_cast<float>(yfov);
    scene_.viewpoints.push_back(v);
  }

  // Frames the bounding sphere from +z and a little above, so every file has a usable camera.
  void addDefaultViewpoint() {
    Bounds b = scene_.bounds();
    Viewpoint v;
    v.name = "default";
    v.yfovRadians = 0.8f;
    float radius = std::max(0.5f * glm::length(b.extent()), 1e-3f);
    float distance = 1.1f * radius / std::sin(0.5f * v.yfovRadians);
    v.target = b.center();
    v.position = b.center() + distance * glm::normalize(glm::vec3(0.0f, 0.3f, 1.0f));
    scene_.viewpoints.push_back(v);
  }

  Source src_;
  Scene scene_;
  std::vector<std::optional<std::vector<Triangle>>> meshCache_;
  std::set<std::string> skippedModes_;  // non-triangle modes met, named in the "no triangles" error
  int defaultMaterial_ = -1;
};

// tinygltf reads a URI that names a directory ("uri": ".") as a file of 2^63 bytes and allocates that (found
// by tests/fuzz; fopen opens a directory, so tinygltf's own check passes it): only regular files exist for
// it, anything else is "File not found" in the load error, in tinygltf 2.7 (Debian 12) and 2.9 (Debian 13)
// alike, since both look a URI up through FileExists before reading it.
bool regularFileExists(const std::string& path, void*) {
  std::error_code ec;
  return std::filesystem::is_regular_file(path, ec);
}

// tinygltf 2.8 and later (Debian 13) also ask for a file's size, and take the callbacks only when all are
// given; 2.7 (Debian 12) has no such callback.
template <class Fs>
void setFileSizeCallback(Fs& fs) {
  if constexpr (requires { fs.GetFileSizeInBytes; })
    fs.GetFileSizeInBytes = [](size_t* size, std::string* err, const std::string& path, void*) {
      std::error_code ec;
      const uintmax_t bytes = std::filesystem::file_size(path, ec);
      if (ec || bytes == 0) {  // tinygltf refuses empty files too
        if (err) *err += "'" + path + "' is empty or unreadable\n";
        return false;
      }
      *size = static_cast<size_t>(bytes);
      return true;
    };
}

void useRegularFilesOnly(tinygltf::TinyGLTF& loader) {
  tinygltf::FsCallbacks fs{};
  fs.FileExists = &regularFileExists;
  fs.ExpandFilePath = &tinygltf::ExpandFilePath;
  fs.ReadWholeFile = &tinygltf::ReadWholeFile;
  fs.WriteWholeFile = &tinygltf::WriteWholeFile;
  setFileSizeCallback(fs);
  loader.SetFsCallbacks(fs);
}

}  // namespace

Scene loadGltf(const std::string& path) {
  std::filesystem::path p(path);
  std::string ext = lowercase(p.extension().string());
  if (ext != ".gltf" && ext != ".glb") throw SceneLoadError(path + ": not a .gltf or .glb file");

  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(&gltf::storeEncodedImage, nullptr);
  useRegularFilesOnly(loader);
  tinygltf::Model model;
  std::string err, warn;
  bool ok = false;
  try {
    ok = ext == ".glb" ? loader.LoadBinaryFromFile(&model, &err, &warn, path)
                       : loader.LoadASCIIFromFile(&model, &err, &warn, path);
  } catch (const std::exception& e) {  // its JSON library may throw on unexpected value types
    throw SceneLoadError(path + ": " + e.what());
  }
  if (!warn.empty()) gltf::printLoadWarnings(path, warn, model);
  if (!ok) {
    while (!err.empty() && std::isspace(static_cast<unsigned char>(err.back()))) err.pop_back();
    throw SceneLoadError(path + ": " + (err.empty() ? std::string("tinygltf could not load the file") : err));
  }
  return Converter(model, path).run(p.stem().string());
}

}  // namespace raylab
