// The scene model every loader produces and the renderer consumes: a flat triangle soup with one material
// per triangle, textures as RGBA8, and named viewpoints. Deliberately unindexed: the BVH reorders
// triangles anyway, and the path tracer needs nothing per vertex but positions and texture coordinates.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace raylab {

struct Bounds {
  glm::vec3 min{1e30f};
  glm::vec3 max{-1e30f};
  void grow(const glm::vec3& p) { min = glm::min(min, p); max = glm::max(max, p); }
  void grow(const Bounds& b) { min = glm::min(min, b.min); max = glm::max(max, b.max); }
  bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
  glm::vec3 extent() const { return empty() ? glm::vec3(0.0f) : max - min; }
  glm::vec3 center() const { return 0.5f * (min + max); }
};

struct Material {
  std::string name;
  glm::vec3 baseColor{0.8f};
  int baseColorTexture = -1;  // index into Scene::textures, -1 for none
  glm::vec3 emissive{0.0f};   // emitted radiance
  float metallic = 0.0f;
  float roughness = 1.0f;
  float specularWeight = 1.0f;  // 0: pure Lambert (no GGX lobe)
  bool isEmissive() const { return emissive.x > 0.0f || emissive.y > 0.0f || emissive.z > 0.0f; }
};

struct Texture {
  std::string name;
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<uint32_t> rgba8;  // width * height texels, R in the low byte, sRGB-encoded colour
};

// A named camera: where it stands, what it looks at, vertical field of view.
struct Viewpoint {
  std::string name;
  glm::vec3 position{0.0f, 0.0f, 5.0f};
  glm::vec3 target{0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float yfovRadians = 0.8f;
};

// The same camera: everything a render sees (the name is not part of it).
inline bool sameCamera(const Viewpoint& a, const Viewpoint& b) {
  return a.position == b.position && a.target == b.target && a.up == b.up && a.yfovRadians == b.yfovRadians;
}

struct Triangle {
  glm::vec3 v[3];
  glm::vec2 uv[3] = {glm::vec2(0.0f), glm::vec2(0.0f), glm::vec2(0.0f)};
  uint32_t material = 0;
};

struct Scene {
  std::string name;
  std::vector<Triangle> triangles;
  std::vector<Material> materials;
  std::vector<Texture> textures;
  std::vector<Viewpoint> viewpoints;  // the first is the default
  glm::vec3 skyColor{0.0f};           // constant radiance of rays that leave the scene
  std::vector<std::string> loadWarnings;  // what the loader skipped (missing textures, ...), for the UI

  Bounds bounds() const;
  const Viewpoint* findViewpoint(const std::string& name) const;
  // Names of all viewpoints, comma separated, for error messages.
  std::string viewpointList() const;
};

// Thrown by every loader for input it cannot use; the message names the file and the problem.
// The CLI turns it into exit code 3.
struct SceneLoadError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace raylab
