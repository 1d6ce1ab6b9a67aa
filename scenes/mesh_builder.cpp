#include "scenes/mesh_builder.h"

#include <algorithm>
#include <cmath>

namespace raylab {

namespace {

// Six times the signed volume of the tetrahedron (o, triangle) (divergence theorem): the sum over a
// closed solid is positive exactly when its triangles face outwards. `o` is a point near the solid,
// so that far from the scene origin the sum does not drown in float cancellation.
float signedVolume6(const Triangle& t, const glm::vec3& o) {
  return glm::dot(t.v[0] - o, glm::cross(t.v[1] - o, t.v[2] - o));
}

// Any vector perpendicular to `n` (n need not be normalised).
glm::vec3 perpendicular(const glm::vec3& n) {
  glm::vec3 a = std::fabs(n.x) < 0.9f * glm::length(n) ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  return glm::normalize(glm::cross(n, a));
}

}  // namespace

uint32_t MeshBuilder::material(const Material& m) {
  scene_.materials.push_back(m);
  return static_cast<uint32_t>(scene_.materials.size() - 1);
}

void MeshBuilder::triangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, uint32_t mat) {
  // Reject slivers relative to the triangle's own size, not an absolute area: the temple is built
  // at any `size`, and a tiny but well-shaped triangle is fine.
  float longest = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
  float doubleArea = glm::length(glm::cross(b - a, c - a));
  if (!(doubleArea > 1e-5f * longest * longest)) {
    ++skipped_;
    return;
  }
  Triangle t;
  t.v[0] = a;
  t.v[1] = b;
  t.v[2] = c;
  t.uv[1] = glm::vec2(1.0f, 0.0f);
  t.uv[2] = glm::vec2(1.0f, 1.0f);
  t.material = mat;
  scene_.triangles.push_back(t);
}

void MeshBuilder::quad(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& d,
                       uint32_t mat) {
  triangle(a, b, c, mat);
  triangle(a, c, d, mat);
}

void MeshBuilder::windOutwards(size_t first, const glm::vec3& nearby) {
  float volume = 0.0f;
  for (size_t i = first; i < scene_.triangles.size(); ++i)
    volume += signedVolume6(scene_.triangles[i], nearby);
  if (volume >= 0.0f) return;
  for (size_t i = first; i < scene_.triangles.size(); ++i) {
    std::swap(scene_.triangles[i].v[1], scene_.triangles[i].v[2]);
    std::swap(scene_.triangles[i].uv[1], scene_.triangles[i].uv[2]);
  }
}

void MeshBuilder::hexahedron(const std::array<glm::vec3, 8>& c, uint32_t mat) {
  size_t first = scene_.triangles.size();
  quad(c[0], c[1], c[2], c[3], mat);
  quad(c[4], c[7], c[6], c[5], mat);
  for (int i = 0; i < 4; ++i) {
    int j = (i + 1) % 4;
    quad(c[i], c[i + 4], c[j + 4], c[j], mat);
  }
  windOutwards(first, c[0]);
}

void MeshBuilder::box(const glm::vec3& lo, const glm::vec3& hi, uint32_t mat) {
  hexahedron({glm::vec3(lo.x, lo.y, lo.z), glm::vec3(hi.x, lo.y, lo.z), glm::vec3(hi.x, lo.y, hi.z),
              glm::vec3(lo.x, lo.y, hi.z), glm::vec3(lo.x, hi.y, lo.z), glm::vec3(hi.x, hi.y, lo.z),
              glm::vec3(hi.x, hi.y, hi.z), glm::vec3(lo.x, hi.y, hi.z)},
             mat);
}

void MeshBuilder::orientedBox(const glm::vec3& center, const glm::vec3& half, float yaw, float tilt,
                              uint32_t mat) {
  glm::vec3 ax(std::cos(yaw), 0.0f, -std::sin(yaw));
  glm::vec3 az(std::sin(yaw), 0.0f, std::cos(yaw));
  glm::vec3 ay(0.0f, 1.0f, 0.0f);
  // Tilt around the box's own x axis.
  glm::vec3 ty = std::cos(tilt) * ay + std::sin(tilt) * az;
  glm::vec3 tz = -std::sin(tilt) * ay + std::cos(tilt) * az;
  auto corner = [&](float sx, float sy, float sz) {
    return center + sx * half.x * ax + sy * half.y * ty + sz * half.z * tz;
  };
  hexahedron({corner(-1, -1, -1), corner(1, -1, -1), corner(1, -1, 1), corner(-1, -1, 1), corner(-1, 1, -1),
              corner(1, 1, -1), corner(1, 1, 1), corner(-1, 1, 1)},
             mat);
}

void MeshBuilder::cylinder(const glm::vec3& base, const glm::vec3& axis, float radius, int segments,
                           uint32_t mat) {
  segments = std::max(segments, 3);
  glm::vec3 u = perpendicular(axis) * radius;
  glm::vec3 v = glm::normalize(glm::cross(axis, u)) * radius;
  glm::vec3 top = base + axis;
  size_t first = scene_.triangles.size();
  // Ring vertices are computed once and shared by the side and the caps, so the solid is closed
  // exactly (bit-identical shared edges), not just up to rounding.
  std::vector<glm::vec3> ring(static_cast<size_t>(segments));
  for (int i = 0; i < segments; ++i) {
    float a = 2.0f * 3.14159265358979f * static_cast<float>(i) / static_cast<float>(segments);
    ring[static_cast<size_t>(i)] = std::cos(a) * u + std::sin(a) * v;
  }
  for (int i = 0; i < segments; ++i) {
    const glm::vec3& r0 = ring[static_cast<size_t>(i)];
    const glm::vec3& r1 = ring[static_cast<size_t>((i + 1) % segments)];
    quad(base + r0, base + r1, top + r1, top + r0, mat);
    triangle(base, base + r1, base + r0, mat);
    triangle(top, top + r0, top + r1, mat);
  }
  windOutwards(first, base);
}

uint64_t MeshBuilder::latticeSolidTriangles(const glm::ivec3& cells) {
  glm::u64vec3 n(glm::max(cells, glm::ivec3(1)));
  return 4 * (n.x * n.y + n.y * n.z + n.z * n.x);
}

void MeshBuilder::latticeSolid(const glm::ivec3& cells, const LatticePoint& point, uint32_t mat) {
  const glm::ivec3 n = glm::max(cells, glm::ivec3(1));
  size_t first = scene_.triangles.size();
  std::vector<glm::vec3> grid;
  // The face at lattice coordinate a = 0 or n[a], spanned by the axes b and c; (b, c, a) is right-handed,
  // so the quad (i, j), (i+1, j), (i+1, j+1), (i, j+1) faces +a. windOutwards settles maps that mirror.
  for (int a = 0; a < 3; ++a) {
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    const size_t rowLength = static_cast<size_t>(n[b]) + 1;
    for (int side = 0; side < 2; ++side) {
      grid.resize(rowLength * (static_cast<size_t>(n[c]) + 1));
      glm::ivec3 p(0);
      p[a] = side ? n[a] : 0;
      for (p[c] = 0; p[c] <= n[c]; ++p[c])
        for (p[b] = 0; p[b] <= n[b]; ++p[b]) grid[static_cast<size_t>(p[c]) * rowLength + static_cast<size_t>(p[b])] = point(p);
      for (size_t j = 0; j < static_cast<size_t>(n[c]); ++j)
        for (size_t i = 0; i < static_cast<size_t>(n[b]); ++i) {
          const glm::vec3& v00 = grid[j * rowLength + i];
          const glm::vec3& v10 = grid[j * rowLength + i + 1];
          const glm::vec3& v11 = grid[(j + 1) * rowLength + i + 1];
          const glm::vec3& v01 = grid[(j + 1) * rowLength + i];
          if (side)
            quad(v00, v10, v11, v01, mat);
          else
            quad(v00, v01, v11, v10, mat);
        }
    }
  }
  windOutwards(first, point(glm::ivec3(0)));
}

}  // namespace raylab
