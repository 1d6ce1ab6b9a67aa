// The white-furnace scene: a closed, uniformly emitting and reflecting sphere seen from its centre.
// Every path hits the sphere at every bounce, so a correct path tracer's mean radiance after B bounces
// is exactly emission * (1 + albedo + ... + albedo^(B-1)), whatever the sampling: a test with an
// analytic answer for the whole bounce loop, sorting included.
#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "scenes/procedural.h"

namespace raylab {

namespace {

// Icosahedron subdivided `subdivisions` times, vertices on the unit sphere. Edge midpoints are
// cached per vertex pair, so neighbouring triangles share bit-identical vertices and the mesh is
// closed (every edge belongs to exactly two triangles); a ray from the centre cannot escape.
struct Icosphere {
  std::vector<glm::vec3> vertices;
  std::vector<glm::uvec3> faces;
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoints;

  uint32_t midpoint(uint32_t a, uint32_t b) {
    auto key = std::minmax(a, b);
    auto [it, inserted] = midpoints.try_emplace({key.first, key.second}, 0u);
    if (inserted) {
      vertices.push_back(glm::normalize(vertices[a] + vertices[b]));
      it->second = static_cast<uint32_t>(vertices.size() - 1);
    }
    return it->second;
  }
};

Icosphere makeIcosphere(int subdivisions) {
  Icosphere s;
  const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
  for (glm::vec3 v : {glm::vec3(-1, t, 0), glm::vec3(1, t, 0), glm::vec3(-1, -t, 0), glm::vec3(1, -t, 0),
                      glm::vec3(0, -1, t), glm::vec3(0, 1, t), glm::vec3(0, -1, -t), glm::vec3(0, 1, -t),
                      glm::vec3(t, 0, -1), glm::vec3(t, 0, 1), glm::vec3(-t, 0, -1), glm::vec3(-t, 0, 1)})
    s.vertices.push_back(glm::normalize(v));
  // Counter-clockwise seen from outside.
  s.faces = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
             {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
             {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int level = 0; level < subdivisions; ++level) {
    std::vector<glm::uvec3> finer;
    finer.reserve(s.faces.size() * 4);
    for (const glm::uvec3& f : s.faces) {
      uint32_t ab = s.midpoint(f.x, f.y), bc = s.midpoint(f.y, f.z), ca = s.midpoint(f.z, f.x);
      finer.insert(finer.end(), {{f.x, ab, ca}, {f.y, bc, ab}, {f.z, ca, bc}, {ab, bc, ca}});
    }
    s.faces = std::move(finer);
    s.midpoints.clear();
  }
  return s;
}

}  // namespace

Scene makeFurnace(float albedo, float emission, int subdivisions) {
  Scene scene;
  scene.name = "furnace";
  scene.skyColor = glm::vec3(0.0f);
  Material m;
  m.name = "furnace";
  m.baseColor = glm::vec3(albedo);
  m.emissive = glm::vec3(emission);
  m.metallic = 0.0f;
  m.roughness = 1.0f;
  m.specularWeight = 0.0f;  // pure Lambert, so the analytic answer holds
  scene.materials.push_back(m);

  // More than 6 levels (81,920 triangles) buys no accuracy and costs memory; fewer than 0 means none.
  Icosphere s = makeIcosphere(subdivisions < 0 ? 0 : (subdivisions > 6 ? 6 : subdivisions));
  scene.triangles.reserve(s.faces.size());
  for (const glm::uvec3& f : s.faces) {
    Triangle t;
    t.v[0] = s.vertices[f.x];
    t.v[1] = s.vertices[f.y];
    t.v[2] = s.vertices[f.z];
    t.material = 0;
    scene.triangles.push_back(t);
  }

  Viewpoint center;
  center.name = "center";
  center.position = glm::vec3(0.0f);
  center.target = glm::vec3(0.0f, 0.0f, -1.0f);
  center.yfovRadians = 1.0f;
  scene.viewpoints.push_back(center);
  return scene;
}

}  // namespace raylab
