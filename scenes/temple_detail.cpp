// temple-detail:N. The detail is a fixed list of closed solids inside the hall (where the "hall" viewpoint's
// paths bounce), each a displaced box lattice (MeshBuilder::latticeSolid). One edge length for the whole
// list sets every solid's cells, so triangles are spread evenly over the detail's surface; the edge is found
// by bisection on the exact triangle count before anything is built.
#include "scenes/temple_detail.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <stdexcept>
#include <vector>

#include "scenes/mesh_builder.h"
#include "scenes/procedural.h"
#include "scenes/splitmix_rng.h"
#include "scenes/temple_layout.h"
#include "scenes/value_noise.h"

namespace raylab {
namespace {

namespace hall = temple_layout;
constexpr uint32_t kSeed = 11;
constexpr int kBoulders = 40;

// One solid of the detail: where each lattice point goes, and the length of its surface along each lattice
// axis, from which an edge length gives its cells.
struct DetailSolid {
  glm::vec3 lengths;  // 0: a single cell (a slab's thickness)
  std::function<glm::vec3(const glm::ivec3& lattice, const glm::ivec3& cells)> place;
  uint32_t material = 0;

  glm::ivec3 cellsAt(float edge) const {
    glm::ivec3 cells(1);
    for (int a = 0; a < 3; ++a)
      if (lengths[a] > 0.0f) cells[a] = static_cast<int>(std::clamp(std::lround(lengths[a] / edge), 1l, 1l << 20));
    return cells;
  }
};

// Flagstones in running bond with chamfered edges, each stone at its own height, with a little wear.
float pavementHeight(float u, float v) {
  const float length = 1.4f, depth = 0.9f, chamfer = 0.04f;
  float row = std::floor(v / depth);
  float su = u / length + 0.5f * std::fmod(std::fabs(row), 2.0f);
  float col = std::floor(su);
  float fu = su - col, fv = v / depth - row;
  float edge = std::min(std::min(fu, 1.0f - fu) * length, std::min(fv, 1.0f - fv) * depth);
  float bevel = glm::smoothstep(0.0f, chamfer, edge);
  float stone = 0.03f + 0.02f * latticeRandom(glm::ivec3(int(col), int(row), 0), kSeed);
  return bevel * stone + 0.006f * valueNoise(glm::vec3(6.0f * u, 6.0f * v, 0.0f), kSeed + 1);
}

// Coffered wall panels: a raised frame around each 2.2 m square and an eight-lobed rosette in its middle.
float reliefHeight(float u, float v) {
  const float size = 2.2f;
  float fu = u / size - std::floor(u / size), fv = v / size - std::floor(v / size);
  float edge = std::min(std::min(fu, 1.0f - fu), std::min(fv, 1.0f - fv)) * size;
  float frame = 0.12f * (1.0f - glm::smoothstep(0.1f, 0.25f, edge));
  glm::vec2 d = (glm::vec2(fu, fv) - 0.5f) * size;
  float lobes = 0.7f + 0.3f * std::cos(8.0f * std::atan2(d.y, d.x));
  float rosette = 0.1f * std::max(0.0f, 1.0f - glm::length(d) / 0.7f) * lobes;
  return std::max(frame, rosette) + 0.01f * valueNoise(glm::vec3(5.0f * u, 5.0f * v, 0.0f), kSeed + 2);
}

// A slab whose corner is `origin`, spanned by `along` (length lu) and `up` (length lv), `thickness` thick
// towards `out` plus height(u, v) there. Lattice axes: x along, y out (one cell), z up.
DetailSolid slab(glm::vec3 origin, glm::vec3 along, float lu, glm::vec3 up, float lv, glm::vec3 out,
                 float thickness, float (*height)(float, float), uint32_t mat) {
  return {glm::vec3(lu, 0.0f, lv),
          [=](const glm::ivec3& p, const glm::ivec3& cells) {
            float u = lu * static_cast<float>(p.x) / static_cast<float>(cells.x);
            float v = lv * static_cast<float>(p.z) / static_cast<float>(cells.z);
            float rise = p.y == 0 ? 0.0f : thickness + height(u, v);
            return origin + u * along + v * up + rise * out;
          },
          mat};
}

// A fluted sleeve around a column shaft: 20 flutes, never thinner than the shaft it hides. Lattice x and
// z go around (the square's boundary projected onto the circle), y up; the caps are the square mapped
// onto the disc.
DetailSolid flutedSleeve(glm::vec3 base, float height, float minRadius, uint32_t mat) {
  const float radius = minRadius + 0.06f;
  return {glm::vec3(0.5f * kPi * radius, height, 0.5f * kPi * radius),
          [=](const glm::ivec3& p, const glm::ivec3& cells) {
            glm::vec2 c(2.0f * static_cast<float>(p.x) / static_cast<float>(cells.x) - 1.0f,
                        2.0f * static_cast<float>(p.z) / static_cast<float>(cells.z) - 1.0f);
            float y = height * static_cast<float>(p.y) / static_cast<float>(cells.y);
            float angle = std::atan2(c.y, c.x);
            glm::vec3 radial(std::cos(angle), 0.0f, std::sin(angle));
            float flute = 0.035f * (0.5f + 0.5f * std::cos(20.0f * angle));
            float wear = 0.008f * valueNoise(3.0f * (radial + glm::vec3(base.x, y, base.z)), kSeed + 3);
            float r = std::max(std::fabs(c.x), std::fabs(c.y)) * (radius - 0.02f - flute + wear);
            return base + glm::vec3(0.0f, y, 0.0f) + r * radial;
          },
          mat};
}

// A lumpy, flattened boulder: the cube lattice projected onto a sphere and pushed out by two octaves of noise.
DetailSolid boulder(glm::vec3 center, float radius, float flatten, uint32_t seed, uint32_t mat) {
  const glm::vec3 squash(1.0f, flatten, 1.0f);
  return {glm::vec3(0.5f * kPi * radius),
          [=](const glm::ivec3& p, const glm::ivec3& cells) {
            glm::vec3 d = glm::normalize(2.0f * glm::vec3(p) / glm::vec3(cells) - 1.0f);
            float r = radius * (1.0f + 0.22f * valueNoise(1.7f * d, seed) + 0.07f * valueNoise(5.0f * d, seed + 1));
            return center + squash * (r * d);
          },
          mat};
}

uint32_t materialNamed(const Scene& scene, const char* name) {
  for (size_t i = 0; i < scene.materials.size(); ++i)
    if (scene.materials[i].name == name) return static_cast<uint32_t>(i);
  throw std::logic_error(std::string("temple-detail: the temple has no material ") + name);
}

std::vector<DetailSolid> hallDetail(const Scene& temple, int columnsPerSide) {
  const uint32_t floor = materialNamed(temple, "floor"), stone = materialNamed(temple, "stone"),
                 marble = materialNamed(temple, "marble");
  const float west = hall::kHallInnerWest, east = hall::kHallInnerEast;
  const float south = hall::kHallInnerSouth, north = hall::kHallInnerNorth;
  const glm::vec3 x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  std::vector<DetailSolid> solids;
  // The pavement: 0.25 below the floor to a little above it, wall to wall.
  solids.push_back(slab({west, -0.25f, south}, x, east - west, z, north - south, y, 0.3f, pavementHeight, floor));
  // Reliefs on the inner faces of the side walls and the south wall (above the dais); the north wall has the
  // windows. They stop below the beams and architraves.
  const float wallTop = 16.3f;
  solids.push_back(slab({west - 0.05f, 0.8f, south + 1.0f}, z, north - south - 2.0f, y, wallTop - 0.8f, x, 0.15f,
                        reliefHeight, stone));
  solids.push_back(slab({east + 0.05f, 0.8f, south + 1.0f}, z, north - south - 2.0f, y, wallTop - 0.8f, -x, 0.15f,
                        reliefHeight, stone));
  const float daisClear = hall::kDaisTop + 0.3f;
  solids.push_back(slab({west + 1.0f, daisClear, south - 0.05f}, x, east - west - 2.0f, y, wallTop - daisClear, z,
                        0.15f, reliefHeight, stone));
  // A fluted sleeve on every hall column, between plinth and capital.
  const int columns = std::clamp(columnsPerSide, 2, 64);
  const float sleeveBase = hall::kPlinthTop - 0.05f;
  const float sleeveHeight = hall::kHallColumnHeight - hall::kCapitalDepth - sleeveBase + 0.05f;
  for (float cx : {-hall::kHallColumnX, hall::kHallColumnX})
    for (int i = 0; i < columns; ++i)
      solids.push_back(flutedSleeve({cx, sleeveBase, hall::hallColumnZ(i, columns)}, sleeveHeight,
                                    hall::kHallShaftRadius + 0.02f, marble));
  // Rubble in the aisles between the columns and the side walls, half sunk into the pavement; the nave stays
  // clear so the hall view still sees the dais.
  SplitMixRng rng(kSeed);
  const float aisleInner = hall::kHallColumnX + 2.5f, aisleOuter = east - 1.5f;
  for (int i = 0; i < kBoulders; ++i) {
    float side = i % 2 ? 1.0f : -1.0f;
    float bx = side * rng.uniform(aisleInner, aisleOuter), bz = rng.uniform(south + 2.0f, north - 2.0f);
    float t = rng.uniform(0.0f, 1.0f);
    float radius = 0.25f + 0.85f * t * t;
    float flatten = rng.uniform(0.5f, 0.8f);
    solids.push_back(boulder({bx, 0.3f * radius * flatten, bz}, radius, flatten, kSeed + 10 + 2 * i, stone));
  }
  return solids;
}

uint64_t trianglesAt(const std::vector<DetailSolid>& solids, float edge) {
  uint64_t total = 0;
  for (const DetailSolid& s : solids) total += MeshBuilder::latticeSolidTriangles(s.cellsAt(edge));
  return total;
}

// The edge length whose triangle count is nearest `budget`. The count only falls as the edge grows, so
// bisect (in log space) between an edge that gives too many and one that gives at most the budget.
float edgeFor(const std::vector<DetailSolid>& solids, uint64_t budget) {
  float tooFine = 1e-4f, fits = 1e3f;
  for (int i = 0; i < 64; ++i) {
    float mid = std::sqrt(tooFine * fits);
    (trianglesAt(solids, mid) > budget ? tooFine : fits) = mid;
  }
  auto miss = [&](float edge) {
    uint64_t n = trianglesAt(solids, edge);
    return n > budget ? n - budget : budget - n;
  };
  return miss(tooFine) < miss(fits) ? tooFine : fits;
}

}  // namespace

bool isTempleDetailName(const std::string& name) {
  const std::string family = kTempleDetailName;
  return name.compare(0, family.size(), family) == 0 && (name.size() == family.size() || name[family.size()] == ':');
}

uint32_t parseTempleDetailTriangles(const std::string& name) {
  const std::string family = kTempleDetailName;
  if (!isTempleDetailName(name)) throw std::invalid_argument("'" + name + "' is not a " + family + " scene");
  if (name.size() == family.size()) return kTempleDetailDefaultTriangles;
  const std::string size = name.substr(family.size() + 1);
  char* end = nullptr;
  errno = 0;
  double n = std::strtod(size.c_str(), &end);
  bool number = !size.empty() && end == size.c_str() + size.size() && errno != ERANGE && std::isfinite(n);
  if (!number || n < kTempleDetailMinTriangles - 0.5 || n >= kTempleDetailMaxTriangles + 0.5)
    throw std::invalid_argument("scene " + name + ": the size after '" + family +
                                ":' is the triangle count, a number from 10000 (1e4) to 30000000 (3e7), got '" + size +
                                "' (e.g. " + family + ":2e6)");
  return static_cast<uint32_t>(std::lround(n));
}

Scene makeTempleDetail(uint32_t triangles) {
  TempleParams params;
  Scene scene = makeTemple(params);
  scene.name = std::string(kTempleDetailName) + ":" + std::to_string(triangles);
  std::vector<DetailSolid> solids = hallDetail(scene, params.columnsPerSide);
  uint64_t budget = triangles > scene.triangles.size() ? triangles - scene.triangles.size() : 0;
  float edge = edgeFor(solids, budget);
  scene.triangles.reserve(scene.triangles.size() + trianglesAt(solids, edge));
  MeshBuilder builder(scene);
  for (const DetailSolid& s : solids) {
    glm::ivec3 cells = s.cellsAt(edge);
    builder.latticeSolid(cells, [&](const glm::ivec3& p) { return s.place(p, cells); }, s.material);
  }
  // The detail is in the hall, so its view comes first (the default).
  std::stable_partition(scene.viewpoints.begin(), scene.viewpoints.end(),
                        [](const Viewpoint& v) { return v.name == "hall"; });
  return scene;
}

}  // namespace raylab
