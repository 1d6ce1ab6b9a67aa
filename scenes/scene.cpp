#include "scenes/scene.h"

namespace raylab {

Bounds Scene::bounds() const {
  Bounds b;
  for (const Triangle& t : triangles)
    for (const glm::vec3& v : t.v) b.grow(v);
  return b;
}

const Viewpoint* Scene::findViewpoint(const std::string& wanted) const {
  for (const Viewpoint& v : viewpoints)
    if (v.name == wanted) return &v;
  return nullptr;
}

std::string Scene::viewpointList() const {
  std::string list;
  for (const Viewpoint& v : viewpoints) list += (list.empty() ? "" : ", ") + v.name;
  return list;
}

}  // namespace raylab
