// The procedural temple, the lab's default scene. Its parts are chosen for what a ray-reordering
// study needs: an alley where primary rays nearly all hit and secondary rays bounce between close
// walls, a roofed hall where paths scatter longest, and an open courtyard where many rays escape to
// the sky. Everything is a closed solid (MeshBuilder), so the hall is light-tight but for its
// windows and door. Layout at size 1 (x east, y up, z north), later scaled by TempleParams::size:
//   ground and perimeter wall  x, z in [-75, 75]
//   hall                        x in [-36, 36], z in [-70, -24], roofed at y = 18..19.5
//   courtyard                   north of the hall, colonnades at x = -60 and x = 30, arcade at z = 58
//   alley                       x in [50, 56] between two tall buildings (up to y = 38)
#include <algorithm>
#include <cmath>
#include <vector>

#include "scenes/mesh_builder.h"
#include "scenes/procedural.h"
#include "scenes/splitmix_rng.h"
#include "scenes/temple_layout.h"

namespace raylab {

namespace {

using Rng = SplitMixRng;

struct Materials {
  uint32_t stone, floor, marble, plaster, roof, bronze, lampWarm, lampCool;
};

Materials addMaterials(MeshBuilder& b) {
  auto diffuse = [](const char* name, glm::vec3 color, float roughness, float metallic = 0.0f) {
    Material m;
    m.name = name;
    m.baseColor = color;
    m.roughness = roughness;
    m.metallic = metallic;
    return m;
  };
  Materials m;
  m.stone = b.material(diffuse("stone", {0.72f, 0.66f, 0.58f}, 0.85f));
  m.floor = b.material(diffuse("floor", {0.42f, 0.40f, 0.36f}, 0.55f));
  m.marble = b.material(diffuse("marble", {0.88f, 0.87f, 0.84f}, 0.25f));
  m.plaster = b.material(diffuse("plaster", {0.66f, 0.32f, 0.22f}, 0.9f));
  m.roof = b.material(diffuse("roof", {0.30f, 0.26f, 0.24f}, 0.7f));
  m.bronze = b.material(diffuse("bronze", {0.78f, 0.52f, 0.26f}, 0.35f, 1.0f));
  Material warm = diffuse("lamp_warm", {0.9f, 0.9f, 0.9f}, 1.0f);
  warm.emissive = {14.0f, 10.0f, 6.0f};
  m.lampWarm = b.material(warm);
  Material cool = diffuse("lamp_cool", {0.9f, 0.9f, 0.9f}, 1.0f);
  cool.emissive = {6.0f, 8.0f, 12.0f};
  m.lampCool = b.material(cool);
  return m;
}

// Maps wall coordinates (u along the wall, w across it, y up) to the world, for walls along x or z.
glm::vec3 wallPoint(bool alongX, float u, float w, float y) {
  return alongX ? glm::vec3(u, y, w) : glm::vec3(w, y, u);
}

struct Opening {
  float u0, u1, y0, y1;
};

// A wall minus rectangular openings (windows, doors), as boxes in horizontal bands: each band
// between consecutive opening edges is solid except where an opening spans the whole band.
void wallWithOpenings(MeshBuilder& b, bool alongX, float u0, float u1, float w0, float w1, float y0, float y1,
                      const std::vector<Opening>& openings, uint32_t mat) {
  std::vector<float> ys = {y0, y1};
  for (const Opening& o : openings)
    for (float y : {o.y0, o.y1}) ys.push_back(std::clamp(y, y0, y1));
  std::sort(ys.begin(), ys.end());
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
  for (size_t i = 0; i + 1 < ys.size(); ++i) {
    float ya = ys[i], yb = ys[i + 1];
    std::vector<Opening> cut;
    for (const Opening& o : openings)
      if (o.y0 <= ya && o.y1 >= yb) cut.push_back(o);
    std::sort(cut.begin(), cut.end(), [](const Opening& a, const Opening& c) { return a.u0 < c.u0; });
    float u = u0;
    auto solid = [&](float ua, float ub) {
      if (ub - ua > 1e-3f) b.box(wallPoint(alongX, ua, w0, ya), wallPoint(alongX, ub, w1, yb), mat);
    };
    for (const Opening& o : cut) {
      solid(u, o.u0);
      u = std::max(u, o.u1);
    }
    solid(u, u1);
  }
}

// The ring of an arch whose opening is a half circle of radius r and whose outline is a square of
// half size R (so the spandrels are filled): one hexahedron per angular segment. `segments` is a
// multiple of 4 so the square's corners (45 and 135 degrees) are segment boundaries.
void archRing(MeshBuilder& b, bool alongX, float u, float w, float springY, float r, float R, float depth,
              int segments, uint32_t mat) {
  auto point = [&](float a, bool outer, float side) {
    glm::vec2 d(std::cos(a), std::sin(a));
    float t = outer ? R / std::max(std::fabs(d.x), d.y) : r;
    return wallPoint(alongX, u + t * d.x, w + side * 0.5f * depth, springY + t * d.y);
  };
  for (int i = 0; i < segments; ++i) {
    float a0 = kPi * static_cast<float>(i) / static_cast<float>(segments);
    float a1 = kPi * static_cast<float>(i + 1) / static_cast<float>(segments);
    b.hexahedron({point(a0, false, -1), point(a0, true, -1), point(a1, true, -1), point(a1, false, -1),
                  point(a0, false, 1), point(a0, true, 1), point(a1, true, 1), point(a1, false, 1)},
                 mat);
  }
}

// Plinth, round shaft and square capital; the parts overlap slightly so no crack opens between them.
void column(MeshBuilder& b, float x, float z, float height, float radius, int segments, uint32_t base,
            uint32_t shaft) {
  float plinth = 1.4f * radius;
  const float plinthTop = temple_layout::kPlinthTop, capital = temple_layout::kCapitalDepth;
  b.box({x - plinth, 0.0f - 0.1f, z - plinth}, {x + plinth, plinthTop, z + plinth}, base);
  // The shaft runs 0.05 into the plinth and 0.1 into the capital (height - 1.25 = height - capital - plinthTop + 0.1).
  b.cylinder({x, 0.55f, z}, {0.0f, height - 1.25f, 0.0f}, radius, segments, shaft);
  b.box({x - plinth, height - capital, z - plinth}, {x + plinth, height, z + plinth}, base);
}

void lamp(MeshBuilder& b, const glm::vec3& c, float half, uint32_t mat) {
  b.box(c - glm::vec3(half), c + glm::vec3(half), mat);
}

struct Detail {
  int cylinder, arch, rubble, columns;
};

void addGroundAndPerimeter(MeshBuilder& b, const Materials& m) {
  b.box({-75, -1, -75}, {75, 0, 75}, m.floor);
  b.box({-75, -0.5f, 73}, {75, 14, 75}, m.stone);
  b.box({-75, -0.5f, -75}, {75, 14, -73}, m.stone);
  b.box({-75, -0.5f, -73}, {-73, 14, 73}, m.stone);
  b.box({73, -0.5f, -73}, {75, 14, 73}, m.stone);
}

void addHall(MeshBuilder& b, const Materials& m, const Detail& d, Rng& rng) {
  // Windows and the door are all in the north wall: the "hall" viewpoint looks south, away from them.
  std::vector<Opening> north = {
      {-3, 3, -1, 7}, {-26, -20, 5, 11}, {-16, -10, 5, 11}, {10, 16, 5, 11}, {20, 26, 5, 11}};
  wallWithOpenings(b, true, -36, 36, -26, -24, -0.5f, 18, north, m.stone);
  b.box({-36, -0.5f, -70}, {36, 18, -68}, m.stone);
  b.box({-36, -0.5f, -68}, {-34, 18, -26}, m.stone);
  b.box({34, -0.5f, -68}, {36, 18, -26}, m.stone);
  b.box({-37, 18, -71}, {37, 19.5f, -23}, m.roof);
  // Dais and altar at the far end.
  b.box({-10, -0.1f, -68.05f}, {10, 1, -60}, m.marble);
  b.box({-2.5f, 0.9f, -66}, {2.5f, 2.6f, -63.5f}, m.stone);
  // Two rows of columns under architraves, with beams to the side walls: dense geometry to look at.
  namespace hall = temple_layout;
  for (float x : {-hall::kHallColumnX, hall::kHallColumnX}) {
    for (int i = 0; i < d.columns; ++i) {
      float z = hall::hallColumnZ(i, d.columns);
      column(b, x, z, hall::kHallColumnHeight, hall::kHallShaftRadius, d.cylinder, m.stone, m.marble);
      float wall = x < 0 ? -34.5f : 34.5f;
      b.box({std::min(x, wall), 17.0f, z - 0.5f}, {std::max(x, wall), 18.05f, z + 0.5f}, m.roof);
    }
    b.box({x - 1.3f, 16.25f, -61.5f}, {x + 1.3f, 17.3f, -28.5f}, m.stone);
  }
  // Lamps hang on rods over the nave; the seed moves them along it.
  for (int i = 0; i < 3; ++i) {
    float z = -35.0f - 11.0f * static_cast<float>(i) + rng.uniform(-3.0f, 3.0f);
    float y = rng.uniform(9.0f, 12.0f);
    lamp(b, {0, y, z}, 0.5f, m.lampWarm);
    b.box({-0.08f, y + 0.45f, z - 0.08f}, {0.08f, 18.05f, z + 0.08f}, m.bronze);
  }
}

void addCourtyard(MeshBuilder& b, const Materials& m, const Detail& d, Rng& rng) {
  // Colonnades with porticoes along the west perimeter wall and the alley's building.
  struct Colonnade {
    float x, roofLo, roofHi;
  };
  for (const Colonnade& c : {Colonnade{-60, -73.5f, -58.5f}, Colonnade{30, 28.5f, 44.5f}}) {
    for (int i = 0; i < d.columns; ++i) {
      float z = -14.0f + 78.0f * static_cast<float>(i) / static_cast<float>(std::max(d.columns - 1, 1));
      column(b, c.x, z, 9.3f, 0.8f, d.cylinder, m.stone, m.marble);
    }
    b.box({c.x - 1.3f, 9.25f, -16}, {c.x + 1.3f, 10.3f, 66}, m.stone);
    b.box({c.roofLo, 10.3f, -16}, {c.roofHi, 11.0f, 66}, m.roof);
  }
  // A free-standing arcade of six arches, under an entablature.
  const float r = 3.0f, R = 4.2f, spring = 6.0f;
  for (int i = 0; i < 6; ++i) {
    float u = -40.0f + 2.0f * R * static_cast<float>(i);
    b.box({u - R, -0.1f, 57}, {u - r, spring + 0.01f, 59}, m.stone);
    b.box({u + r, -0.1f, 57}, {u + R, spring + 0.01f, 59}, m.stone);
    archRing(b, true, u, 58, spring, r, R, 2.0f, d.arch, m.stone);
  }
  b.box({-40.0f - R, spring + R - 0.01f, 56.8f}, {-40.0f + 11.0f * R, spring + R + 1.0f, 59.2f}, m.marble);
  // Fountain inside a ring of broken columns; the seed decides how much of each column stands.
  const glm::vec3 f(-15, 0, 25);
  b.cylinder(f + glm::vec3(0, -0.1f, 0), {0, 1.0f, 0}, 5.0f, d.cylinder, m.stone);
  b.cylinder(f + glm::vec3(0, 0.8f, 0), {0, 2.4f, 0}, 1.0f, d.cylinder, m.marble);
  b.cylinder(f + glm::vec3(0, 3.1f, 0), {0, 0.5f, 0}, 2.5f, d.cylinder, m.marble);
  lamp(b, f + glm::vec3(0, 4.0f, 0), 0.4f, m.lampCool);
  for (int i = 0; i < 10; ++i) {
    float a = 2.0f * kPi * static_cast<float>(i) / 10.0f;
    glm::vec3 p = f + 12.0f * glm::vec3(std::cos(a), 0, std::sin(a));
    float height = rng.uniform(2.0f, 9.3f);
    column(b, p.x, p.z, height, 0.7f, d.cylinder, m.stone, m.marble);
    if (height < 5.0f) {  // its fallen drum lies beside it
      float yaw = rng.uniform(0.0f, 2.0f * kPi);
      glm::vec3 axis = rng.uniform(2.0f, 4.0f) * glm::vec3(std::cos(yaw), 0, std::sin(yaw));
      b.cylinder(p + glm::vec3(2.0f, 0.6f, 0), axis, 0.7f, d.cylinder, m.marble);
    }
  }
  // Rubble, kept off the fountain.
  for (int i = 0; i < d.rubble; ++i) {
    glm::vec3 c(rng.uniform(-55, 25), 0, rng.uniform(-15, 50));
    glm::vec3 half(rng.uniform(0.15f, 0.9f), rng.uniform(0.1f, 0.5f), rng.uniform(0.15f, 0.9f));
    float yaw = rng.uniform(0, kPi), tilt = rng.uniform(-0.4f, 0.4f);
    if (glm::length(c - f) < 7.0f) continue;
    c.y = 0.6f * half.y;
    b.orientedBox(c, half, yaw, tilt, m.stone);
  }
  // Lamp posts at jittered spots in the four quarters of the courtyard.
  for (glm::vec2 q : {glm::vec2(-45, -8), glm::vec2(15, -8), glm::vec2(-45, 45), glm::vec2(15, 45)}) {
    glm::vec3 p(q.x + rng.uniform(-4, 4), 0, q.y + rng.uniform(-4, 4));
    b.cylinder(p + glm::vec3(0, -0.1f, 0), {0, 4.1f, 0}, 0.15f, d.cylinder, m.bronze);
    lamp(b, p + glm::vec3(0, 4.3f, 0), 0.35f, m.lampWarm);
  }
}

void addAlley(MeshBuilder& b, const Materials& m, const Detail& d, Rng& rng) {
  // Two tall buildings in blocks of jittered height. Their upper storeys overhang the alley
  // (x in [50, 56]) and leave only a 1.5 unit slit of sky, so the alley stays nearly closed above.
  for (int block = 0; block < 6; ++block) {
    float z0 = -73.0f + 24.5f * static_cast<float>(block), z1 = z0 + 24.5f;
    float west = rng.uniform(30, 38), east = rng.uniform(30, 38);
    std::vector<Opening> door;
    if (z0 <= 22 && z1 >= 22) door.push_back({20, 24, -1, 6});  // passage from the courtyard
    wallWithOpenings(b, false, z0, z1, 44, 50, -0.5f, 20.5f, door, m.plaster);
    b.box({44, 20, z0}, {52.25f, west, z1}, m.plaster);
    b.box({56, -0.5f, z0}, {64, 20.5f, z1}, m.plaster);
    b.box({53.75f, 20, z0}, {64, east, z1}, m.plaster);
  }
  b.box({49, -0.5f, 66}, {57, 36, 73}, m.stone);
  b.box({49, -0.5f, -73}, {57, 36, -68}, m.stone);
  // Arches bridge the alley at jittered heights; their feet are buried in the walls.
  for (float z = -54.0f; z < 64.0f; z += 14.0f)
    archRing(b, true, 53, z, rng.uniform(7, 16), 3.0f, 4.5f, 1.5f, d.arch, m.stone);
  // Wall lamps on alternating sides.
  for (int i = 0; i < 4; ++i) {
    float z = -50.0f + 30.0f * static_cast<float>(i) + rng.uniform(-6, 6);
    float x = (i % 2 == 0) ? 50.3f : 55.7f;
    lamp(b, {x, rng.uniform(3.5f, 5.0f), z}, 0.35f, m.lampWarm);
  }
}

Viewpoint view(const char* name, glm::vec3 position, glm::vec3 target, float yfov) {
  Viewpoint v;
  v.name = name;
  v.position = position;
  v.target = target;
  v.yfovRadians = yfov;
  return v;
}

}  // namespace

Scene makeTemple(const TempleParams& p) {
  Scene scene;
  scene.name = "temple";
  scene.skyColor = {0.9f, 0.95f, 1.1f};
  MeshBuilder b(scene);
  int detail = std::clamp(p.detail, 1, 8);
  Detail d{12 * detail, 4 * (2 * detail + 1), 24 * detail, std::clamp(p.columnsPerSide, 2, 64)};
  Materials m = addMaterials(b);
  // One generator per area, each seeded from the seed, so a change in one area's draws does not
  // shift every other area.
  addGroundAndPerimeter(b, m);
  Rng hallRng(p.seed * 4 + 0), courtRng(p.seed * 4 + 1), alleyRng(p.seed * 4 + 2);
  addHall(b, m, d, hallRng);
  addCourtyard(b, m, d, courtRng);
  addAlley(b, m, d, alleyRng);

  // The first is the default: the overview, lit by the open sky, shows the whole scene within seconds; the
  // alley and the hall are lit mostly indirectly and stay dark and noisy for hundreds of samples.
  scene.viewpoints = {
      view("overview", {-115, 95, 125}, {0, 5, 0}, 0.8f),
      view("alley", {53, 2.0f, -66}, {53, 3.5f, 60}, 0.9f),
      view("hall", {0, 4.0f, -29}, {0, 6.0f, -66}, 0.9f),
      view("openings", {-15, 1.7f, 8}, {-15, 25, 45}, 0.9f),
  };
  float s = p.size > 0.0f && std::isfinite(p.size) ? p.size : 1.0f;
  for (Triangle& t : scene.triangles)
    for (glm::vec3& v : t.v) v *= s;
  for (Viewpoint& v : scene.viewpoints) {
    v.position *= s;
    v.target *= s;
  }
  return scene;
}

}  // namespace raylab
