// Appends closed solids (boxes, prisms, cylinders, general hexahedra) to a Scene. The procedural scenes
// are built only from closed, outward-wound solids so that a ray can never slip through a crack between
// two open surfaces, and every triangle the builder emits has a non-zero area.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <vector>

#include "scenes/scene.h"

namespace raylab {

class MeshBuilder {
 public:
  explicit MeshBuilder(Scene& scene) : scene_(scene) {}

  // Adds a material and returns its index, for Triangle::material.
  uint32_t material(const Material& m);

  // One triangle; skipped (and counted in skipped()) if its area is not clearly positive, so
  // callers never produce degenerate triangles even for odd parameters.
  void triangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, uint32_t mat);
  // Two triangles a,b,c and a,c,d (an open quad: closed solids are made of these).
  void quad(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& d, uint32_t mat);

  // A closed six-faced solid. Corners 0..3 are one face, 4..7 the opposite face with corner i+4
  // across from corner i. The winding is chosen from the signed volume, so either order works.
  void hexahedron(const std::array<glm::vec3, 8>& c, uint32_t mat);
  // Axis-aligned box.
  void box(const glm::vec3& lo, const glm::vec3& hi, uint32_t mat);
  // Box of half extents `half` centred at `center`, rotated by `yaw` around +y then `tilt` around
  // the box's own x axis (rubble, fallen blocks).
  void orientedBox(const glm::vec3& center, const glm::vec3& half, float yaw, float tilt, uint32_t mat);
  // Closed cylinder (prism with `segments` sides, at least 3) from `base` along `axis` (any length).
  void cylinder(const glm::vec3& base, const glm::vec3& axis, float radius, int segments, uint32_t mat);

  // A closed solid made from the surface of a box lattice with `cells` quads along each axis (at least one),
  // each lattice point placed by `point`: subdivided and displaced slabs, boulders, fluted shafts. Every
  // point is computed from its integer lattice coordinates, so faces that share an edge share its corners
  // bit for bit and the solid is closed exactly.
  using LatticePoint = std::function<glm::vec3(const glm::ivec3& lattice)>;
  void latticeSolid(const glm::ivec3& cells, const LatticePoint& point, uint32_t mat);
  // Triangles latticeSolid emits for `cells` (when no sliver is skipped).
  static uint64_t latticeSolidTriangles(const glm::ivec3& cells);

  size_t skipped() const { return skipped_; }

 private:
  // Outward normals for a renderer that shades by the geometric normal: flips the triangles appended
  // since `first` (one closed solid) if their signed volume is negative.
  void windOutwards(size_t first, const glm::vec3& nearby);

  Scene& scene_;
  size_t skipped_ = 0;
};

}  // namespace raylab
