// clutter:N. The room (floor, ceiling, four walls with a window, as closed slabs), shelf units along three
// walls with books in every shelf, then loose objects drawn one after another from one random sequence until
// the triangle budget is spent: tables laid with cups and plates, chairs (some tipped over), potted plants
// whose leaves are thin triangle fans, piles of crates and tumbled boxes, and cables sagging from the
// ceiling. Objects may touch or pass into each other (a store room, not a simulation); none comes near a
// camera. What makes it incoherent: rays that leave one surface cross anything from a hand's width of
// empty space to the whole cluttered room, and thin leaves and cables put many BVH boxes in their way.
#include "scenes/clutter.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <vector>

#include "scenes/mesh_builder.h"
#include "scenes/procedural.h"
#include "scenes/splitmix_rng.h"

namespace raylab {
namespace {

// The room's inside: x across, z deep, y up (metres).
constexpr float kRoomX = 7.0f, kRoomZ = 5.0f, kRoomY = 3.2f, kClutterWall = 0.2f;

struct ClutterMaterials {
  uint32_t wall, floor, ceiling, wood, darkWood, metal, ceramic, leaf, pot, cable, crate, light;
  std::array<uint32_t, 6> books;
};

Material clutterMaterial(const char* name, glm::vec3 colour, float roughness = 1.0f, float specular = 0.0f,
                         float metallic = 0.0f) {
  Material m;
  m.name = name;
  m.baseColor = colour;
  m.roughness = roughness;
  m.specularWeight = specular;
  m.metallic = metallic;
  return m;
}

ClutterMaterials addClutterMaterials(MeshBuilder& b) {
  ClutterMaterials m{};
  m.wall = b.material(clutterMaterial("wall", {0.75f, 0.72f, 0.66f}));
  m.floor = b.material(clutterMaterial("floor", {0.45f, 0.33f, 0.22f}, 0.5f, 1.0f));
  m.ceiling = b.material(clutterMaterial("ceiling", {0.8f, 0.8f, 0.8f}));
  m.wood = b.material(clutterMaterial("wood", {0.55f, 0.38f, 0.22f}, 0.6f, 1.0f));
  m.darkWood = b.material(clutterMaterial("dark wood", {0.25f, 0.15f, 0.08f}, 0.5f, 1.0f));
  m.metal = b.material(clutterMaterial("metal", {0.9f, 0.88f, 0.85f}, 0.25f, 1.0f, 1.0f));
  m.ceramic = b.material(clutterMaterial("ceramic", {0.9f, 0.9f, 0.85f}, 0.15f, 1.0f));
  m.leaf = b.material(clutterMaterial("leaf", {0.12f, 0.4f, 0.1f}, 0.7f, 0.5f));
  m.pot = b.material(clutterMaterial("pot", {0.6f, 0.28f, 0.16f}));
  m.cable = b.material(clutterMaterial("cable", {0.05f, 0.05f, 0.05f}, 0.4f, 1.0f));
  m.crate = b.material(clutterMaterial("crate", {0.7f, 0.58f, 0.4f}));
  Material light = clutterMaterial("light", {0.8f, 0.8f, 0.8f});
  light.emissive = {40.0f, 36.0f, 30.0f};
  m.light = b.material(light);
  const glm::vec3 bookColours[] = {{0.6f, 0.1f, 0.1f}, {0.1f, 0.2f, 0.5f}, {0.15f, 0.4f, 0.2f},
                                   {0.7f, 0.6f, 0.3f}, {0.3f, 0.3f, 0.3f}, {0.8f, 0.75f, 0.7f}};
  for (size_t i = 0; i < m.books.size(); ++i) m.books[i] = b.material(clutterMaterial("book", bookColours[i], 0.8f, 0.3f));
  return m;
}

// A box of half extents `half` at `center`, its axes the columns of `r` (any rotation).
void clutterBox(MeshBuilder& b, const glm::vec3& center, const glm::vec3& half, const glm::mat3& r, uint32_t mat) {
  auto corner = [&](float sx, float sy, float sz) { return center + r * (glm::vec3(sx, sy, sz) * half); };
  b.hexahedron({corner(-1, -1, -1), corner(1, -1, -1), corner(1, -1, 1), corner(-1, -1, 1), corner(-1, 1, -1),
                corner(1, 1, -1), corner(1, 1, 1), corner(-1, 1, 1)},
               mat);
}

glm::mat3 clutterYaw(float yaw) {
  return glm::mat3(glm::vec3(std::cos(yaw), 0, -std::sin(yaw)), glm::vec3(0, 1, 0), glm::vec3(std::sin(yaw), 0, std::cos(yaw)));
}

// A uniformly random rotation (from a random unit quaternion).
glm::mat3 clutterRotation(SplitMixRng& rng) {
  float u1 = rng.uniform(0, 1), u2 = rng.uniform(0, 2 * kPi), u3 = rng.uniform(0, 2 * kPi);
  float a = std::sqrt(1 - u1), c = std::sqrt(u1);
  float x = a * std::sin(u2), y = a * std::cos(u2), z = c * std::sin(u3), w = c * std::cos(u3);
  return glm::mat3(glm::vec3(1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)),
                   glm::vec3(2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)),
                   glm::vec3(2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)));
}

// Floor, ceiling and walls as closed slabs; the north wall (z = +kRoomZ) has a window of sky; small lights
// hang just under the ceiling, facing down.
void clutterRoom(MeshBuilder& b, const ClutterMaterials& m) {
  const float X = kRoomX + kClutterWall, Z = kRoomZ + kClutterWall;
  b.box({-X, -kClutterWall, -Z}, {X, 0.0f, Z}, m.floor);
  b.box({-X, kRoomY, -Z}, {X, kRoomY + kClutterWall, Z}, m.ceiling);
  b.box({-X, 0.0f, -Z}, {-kRoomX, kRoomY, Z}, m.wall);
  b.box({kRoomX, 0.0f, -Z}, {X, kRoomY, Z}, m.wall);
  b.box({-kRoomX, 0.0f, -Z}, {kRoomX, kRoomY, -kRoomZ}, m.wall);
  // North wall around a window 3 m wide, 1.2 m high, its sill at 1 m.
  const float wx0 = 1.0f, wx1 = 4.0f, wy0 = 1.0f, wy1 = 2.2f;
  b.box({-kRoomX, 0.0f, kRoomZ}, {wx0, kRoomY, Z}, m.wall);
  b.box({wx1, 0.0f, kRoomZ}, {kRoomX, kRoomY, Z}, m.wall);
  b.box({wx0, 0.0f, kRoomZ}, {wx1, wy0, Z}, m.wall);
  b.box({wx0, wy1, kRoomZ}, {wx1, kRoomY, Z}, m.wall);
  const float ly = kRoomY - 0.02f;
  for (float lx : {-4.5f, 0.0f, 4.5f})
    for (float lz : {-2.5f, 2.5f}) b.quad({lx - 0.3f, ly, lz - 0.3f}, {lx - 0.3f, ly, lz + 0.3f}, {lx + 0.3f, ly, lz + 0.3f}, {lx + 0.3f, ly, lz - 0.3f}, m.light);
}

// A shelf unit standing at `origin` against a wall, running along `along`, `out` pointing into the room:
// two sides, five boards, and books on every board, each its own size, some leaning, some gaps.
void clutterShelfUnit(MeshBuilder& b, SplitMixRng& rng, const ClutterMaterials& m, glm::vec3 origin, glm::vec3 along,
               glm::vec3 out, float length) {
  const float depth = 0.35f, height = 2.4f, board = 0.025f;
  const int boards = 5;
  const glm::vec3 up(0, 1, 0);
  const glm::mat3 frame(along, up, out);
  auto at = [&](float u, float v, float w) { return origin + u * along + v * up + w * out; };
  for (float u : {0.01f, length - 0.01f}) clutterBox(b, at(u, 0.5f * height, 0.5f * depth), {0.01f, 0.5f * height, 0.5f * depth}, frame, m.darkWood);
  for (int k = 0; k < boards; ++k) {
    const float y = 0.1f + k * (height - 0.15f) / (boards - 1);
    clutterBox(b, at(0.5f * length, y, 0.5f * depth), {0.5f * length - 0.02f, 0.5f * board, 0.5f * depth}, frame, m.wood);
    if (k == boards - 1) break;
    for (float u = 0.03f; u < length - 0.08f;) {
      if (rng.uniform(0, 1) < 0.08f) {  // a gap
        u += rng.uniform(0.05f, 0.2f);
        continue;
      }
      const float w = rng.uniform(0.015f, 0.06f), h = rng.uniform(0.16f, 0.34f), d = rng.uniform(0.14f, 0.3f);
      const float lean = rng.uniform(0, 1) < 0.15f ? rng.uniform(-0.5f, 0.5f) : rng.uniform(-0.04f, 0.04f);
      const glm::mat3 r = frame * glm::mat3(glm::vec3(std::cos(lean), std::sin(lean), 0), glm::vec3(-std::sin(lean), std::cos(lean), 0),
                                            glm::vec3(0, 0, 1)) *
                          clutterYaw(rng.uniform(-0.1f, 0.1f));
      const uint32_t colour = m.books[static_cast<size_t>(rng.next() % m.books.size())];
      clutterBox(b, at(u + 0.5f * w, y + 0.5f * board + 0.5f * h * std::cos(lean), 0.5f * d + 0.01f), {0.5f * w, 0.5f * h, 0.5f * d}, r, colour);
      u += w + std::fabs(h * std::sin(lean)) + 0.002f;
    }
  }
}

void clutterShelves(MeshBuilder& b, SplitMixRng& rng, const ClutterMaterials& m) {
  const float unit = 1.6f;
  for (float x = -kRoomX + 0.1f; x + unit <= kRoomX - 0.1f; x += unit + 0.05f)  // the south wall
    clutterShelfUnit(b, rng, m, {x, 0.0f, -kRoomZ}, {1, 0, 0}, {0, 0, 1}, unit);
  for (float side : {-1.0f, 1.0f})  // both side walls, leaving the corners free
    for (float z = -kRoomZ + 0.6f; z + unit <= kRoomZ - 0.6f; z += unit + 0.05f)
      clutterShelfUnit(b, rng, m, {side * kRoomX, 0.0f, side > 0 ? z + unit : z}, {0, 0, side > 0 ? -1.0f : 1.0f},
                {-side, 0, 0}, unit);
}

// Where a loose object may stand: inside the room, off the shelves, away from every camera.
struct ClutterPlacement {
  std::vector<glm::vec3> cameras;
  bool free(const glm::vec3& p, float radius) const {
    for (const glm::vec3& c : cameras)
      if (glm::length(p - c) < radius + 0.7f) return false;
    return true;
  }
};

glm::vec3 clutterFloorSpot(SplitMixRng& rng) {
  return {rng.uniform(-kRoomX + 0.6f, kRoomX - 0.6f), 0.0f, rng.uniform(-kRoomZ + 0.6f, kRoomZ - 0.4f)};
}

// Cups (open-topped look from a short cylinder and a handle), plates and bowls on a table top at `top`.
void clutterTableware(MeshBuilder& b, SplitMixRng& rng, const ClutterMaterials& m, glm::vec3 centre, float halfX, float halfZ,
               float yaw) {
  const glm::mat3 r = clutterYaw(yaw);
  const int n = 3 + static_cast<int>(rng.next() % 8);
  for (int i = 0; i < n; ++i) {
    const glm::vec3 p = centre + r * glm::vec3(rng.uniform(-halfX, halfX) * 0.9f, 0, rng.uniform(-halfZ, halfZ) * 0.9f);
    switch (rng.next() % 4) {
      case 0:  // a plate
        b.cylinder(p, {0, 0.015f, 0}, rng.uniform(0.1f, 0.14f), 16, m.ceramic);
        break;
      case 1:  // a cup with a handle
        b.cylinder(p, {0, rng.uniform(0.07f, 0.11f), 0}, 0.04f, 10, m.ceramic);
        clutterBox(b, p + glm::vec3(0.05f, 0.05f, 0), {0.012f, 0.025f, 0.005f}, glm::mat3(1.0f), m.ceramic);
        break;
      case 2: {  // a bottle, sometimes fallen over
        const bool fallen = rng.uniform(0, 1) < 0.3f;
        const float a = rng.uniform(0, 2 * kPi);
        const glm::vec3 axis = fallen ? glm::vec3(std::cos(a), 0.0f, std::sin(a)) * 0.25f : glm::vec3(0, 0.25f, 0);
        b.cylinder(p + (fallen ? glm::vec3(0, 0.035f, 0) : glm::vec3(0)), axis, 0.035f, 8, m.metal);
        break;
      }
      default:  // cutlery, at any angle
        clutterBox(b, p + glm::vec3(0, 0.004f, 0), {0.09f, 0.003f, 0.008f}, clutterYaw(rng.uniform(0, 2 * kPi)), m.metal);
    }
  }
}

void clutterTable(MeshBuilder& b, SplitMixRng& rng, const ClutterMaterials& m, glm::vec3 p) {
  const float yaw = rng.uniform(0, 2 * kPi), hx = rng.uniform(0.4f, 0.9f), hz = rng.uniform(0.3f, 0.5f), h = 0.75f;
  const glm::mat3 r = clutterYaw(yaw);
  clutterBox(b, p + glm::vec3(0, h - 0.02f, 0), {hx, 0.02f, hz}, r, m.wood);
  for (float sx : {-1.0f, 1.0f})
    for (float sz : {-1.0f, 1.0f})
      clutterBox(b, p + r * glm::vec3(sx * (hx - 0.05f), 0.5f * (h - 0.04f), sz * (hz - 0.05f)), {0.025f, 0.5f * (h - 0.04f), 0.025f}, r, m.wood);
  clutterTableware(b, rng, m, p + glm::vec3(0, h, 0), hx, hz, yaw);
}

void clutterChair(MeshBuilder& b, SplitMixRng& rng, const ClutterMaterials& m, glm::vec3 p) {
  // Built upright around its seat's centre, then turned and, one time in four, tipped onto its back or side.
  glm::mat3 r = clutterYaw(rng.uniform(0, 2 * kPi));
  float lift = 0.0f;
  if (rng.uniform(0, 1) < 0.25f) {
    const float tip = rng.uniform(1.2f, 1.6f);
    r = r * glm::mat3(glm::vec3(1, 0, 0), glm::vec3(0, std::cos(tip), std::sin(tip)), glm::vec3(0, -std::sin(tip), std::cos(tip)));
    lift = 0.25f;
  }
  const glm::vec3 seat = p + glm::vec3(0, 0.45f - lift, 0);
  auto part = [&](glm::vec3 local, glm::vec3 half) { clutterBox(b, seat + r * local, half, r, m.darkWood); };
  part({0, 0, 0}, {0.21f, 0.02f, 0.21f});
  for (float sx : {-1.0f, 1.0f})
    for (float sz : {-1.0f, 1.0f}) part({sx * 0.18f, -0.225f, sz * 0.18f}, {0.018f, 0.225f, 0.018f});
  for (float sx : {-1.0f, 1.0f}) part({sx * 0.18f, 0.25f, -0.19f}, {0.018f, 0.25f, 0.018f});
  for (float y : {0.2f, 0.35f, 0.47f}) part({0, y, -0.19f}, {0.18f, 0.03f, 0.012f});
}

// A pot and a bush of leaves: each leaf a thin fan of triangles from its base out along a bent midrib, long
// and narrow like a grass's or a palm's, pointing every way. Their long thin triangles lie across each other,
// so the BVH cannot part them: a ray through a bush visits many boxes, one beside it few.
// A plant is the only object of thousands of triangles: it stops adding leaves (each whole) once the scene
// has `budget` triangles, so the scene's count ends within one small object of the one asked for.
void pottedPlant(MeshBuilder& b, SplitMixRng& rng, const ClutterMaterials& m, glm::vec3 p, const Scene& scene, size_t budget) {
  const float potR = rng.uniform(0.12f, 0.22f), potH = rng.uniform(0.2f, 0.35f);
  b.cylinder(p, {0, potH, 0}, potR, 12, m.pot);
  // Dense tussocks (pampas grass, a palm's fronds): the number of blades is what brought the unsorted
  // virtual warp efficiency of bounces >= 1 from about 0.45 (60 blades) down to 0.15-0.2 (1e5-1e6 triangles).
  const int leaves = 720 + static_cast<int>(rng.next() % 1440);
  const float size = rng.uniform(0.4f, 1.1f);
  for (int i = 0; i < leaves && scene.triangles.size() < budget; ++i) {
    const glm::vec3 base = p + glm::vec3(rng.uniform(-0.5f, 0.5f) * potR, potH, rng.uniform(-0.5f, 0.5f) * potR);
    const float a = rng.uniform(0, 2 * kPi), rise = rng.uniform(0.3f, 2.5f);
    const glm::vec3 dir = glm::normalize(glm::vec3(std::cos(a), rise, std::sin(a)));
    const glm::vec3 side = glm::normalize(glm::cross(dir, glm::vec3(0, 1, 0)) + glm::vec3(0, rng.uniform(-0.5f, 0.5f), 0));
    const float length = size * rng.uniform(0.5f, 1.0f), width = length * rng.uniform(0.015f, 0.05f);
    constexpr int kSegments = 3;
    glm::vec3 prevL = base, prevR = base;
    for (int s = 1; s <= kSegments; ++s) {
      const float t = static_cast<float>(s) / kSegments;
      const glm::vec3 mid = base + t * length * dir - glm::vec3(0, 0.4f * t * t * length, 0);  // it droops
      const float w = width * std::sin(kPi * std::min(t, 0.9f));
      const glm::vec3 l = mid - w * side, r = mid + w * side;
      b.triangle(base, prevL, l, m.leaf);
      b.triangle(base, r, prevR, m.leaf);
      prevL = l;
      prevR = r;
    }
  }
}

// A pile of crates and tumbled boxes, stacked roughly, some at any angle.
void boxPile(MeshBuilder& b, SplitMixRng& rng, const ClutterMaterials& m, glm::vec3 p) {
  const int n = 3 + static_cast<int>(rng.next() % 10);
  float y = 0.0f;
  for (int i = 0; i < n; ++i) {
    const glm::vec3 half(rng.uniform(0.05f, 0.3f), rng.uniform(0.04f, 0.2f), rng.uniform(0.05f, 0.3f));
    const bool tumbled = rng.uniform(0, 1) < 0.5f;
    const glm::mat3 r = tumbled ? clutterRotation(rng) : clutterYaw(rng.uniform(0, 2 * kPi));
    const glm::vec3 c = p + glm::vec3(rng.uniform(-0.4f, 0.4f), y + half.y, rng.uniform(-0.4f, 0.4f));
    clutterBox(b, c, half, r, rng.uniform(0, 1) < 0.5f ? m.crate : m.books[static_cast<size_t>(rng.next() % m.books.size())]);
    y = rng.uniform(0, 1) < 0.6f ? y + 2.0f * half.y : 0.0f;
    if (y > 1.8f) y = 0.0f;
  }
}

// A cable strung under the ceiling between two hooks (an extension lead, a garland), sagging, in thin
// 4-sided segments; or one hanging straight down to a lamp shade. Their long diagonal segments have
// bounding boxes far larger than themselves: the upper room becomes a web that rays going up must work
// through, while rays going down stop in the clutter at once.
void hangingCable(MeshBuilder& b, SplitMixRng& rng, const ClutterMaterials& m, glm::vec3 p) {
  const glm::vec3 a(p.x, rng.uniform(2.0f, kRoomY), p.z);
  const bool hanging = rng.uniform(0, 1) < 0.15f;
  const glm::vec3 e = clutterFloorSpot(rng) + glm::vec3(0, rng.uniform(2.0f, kRoomY), 0);
  const float sag = rng.uniform(0.1f, 0.8f), drop = rng.uniform(0.5f, 1.5f);
  constexpr int kSegments = 8;
  glm::vec3 prev = hanging ? glm::vec3(p.x, kRoomY, p.z) : a;
  for (int s = 1; s <= kSegments; ++s) {
    const float t = static_cast<float>(s) / kSegments;
    const glm::vec3 q = hanging ? glm::vec3(p.x, kRoomY - t * drop, p.z)
                                : glm::mix(a, e, t) - glm::vec3(0, 4.0f * sag * t * (1 - t), 0);
    b.cylinder(prev, q - prev, 0.006f, 4, m.cable);
    prev = q;
  }
  if (hanging) b.cylinder(prev - glm::vec3(0, 0.12f, 0), {0, 0.12f, 0}, 0.15f, 12, m.metal);  // a lamp shade
}

// Moves the object made of the triangles from `first` on into the room's interior where it pokes out (a
// tumbled box through the floor, a plant's leaves into a wall): it rests on the floor or against the wall.
void clutterKeepInside(Scene& scene, size_t first) {
  Bounds object;
  for (size_t i = first; i < scene.triangles.size(); ++i)
    for (const glm::vec3& v : scene.triangles[i].v) object.grow(v);
  if (object.empty()) return;
  const glm::vec3 lo(-kRoomX, 0.0f, -kRoomZ), hi(kRoomX, kRoomY, kRoomZ);
  glm::vec3 shift(0.0f);
  for (int a = 0; a < 3; ++a) {
    if (object.min[a] < lo[a]) shift[a] = lo[a] - object.min[a];
    else if (object.max[a] > hi[a]) shift[a] = hi[a] - object.max[a];
  }
  if (shift == glm::vec3(0.0f)) return;
  for (size_t i = first; i < scene.triangles.size(); ++i)
    for (glm::vec3& v : scene.triangles[i].v) v += shift;
}

std::vector<Viewpoint> clutterViews() {
  Viewpoint overview{"overview", {-6.2f, 2.6f, 4.2f}, {1.0f, 0.6f, -1.5f}};
  overview.yfovRadians = 1.1f;
  Viewpoint shelvesView{"shelves", {0.5f, 1.5f, 2.5f}, {0.0f, 1.1f, -5.0f}};
  shelvesView.yfovRadians = 1.0f;
  Viewpoint floorView{"floor", {6.2f, 0.5f, -4.2f}, {-2.0f, 0.4f, 2.0f}};
  floorView.yfovRadians = 1.1f;
  return {overview, shelvesView, floorView};
}

}  // namespace

bool isClutterName(const std::string& name) {
  const std::string family = kClutterName;
  return name.compare(0, family.size(), family) == 0 && (name.size() == family.size() || name[family.size()] == ':');
}

uint32_t parseClutterTriangles(const std::string& name) {
  const std::string family = kClutterName;
  if (!isClutterName(name)) throw std::invalid_argument("'" + name + "' is not a " + family + " scene");
  if (name.size() == family.size()) return kClutterDefaultTriangles;
  const std::string size = name.substr(family.size() + 1);
  char* end = nullptr;
  errno = 0;
  const double n = std::strtod(size.c_str(), &end);
  const bool number = !size.empty() && end == size.c_str() + size.size() && errno != ERANGE && std::isfinite(n);
  if (!number || n < kClutterMinTriangles - 0.5 || n >= kClutterMaxTriangles + 0.5)
    throw std::invalid_argument("scene " + name + ": the size after '" + family +
                                ":' is the triangle count, a number from 50000 (5e4) to 3000000 (3e6), got '" + size +
                                "' (e.g. " + family + ":5e5)");
  return static_cast<uint32_t>(std::lround(n));
}

Bounds clutterRoomInterior() {
  Bounds b;
  b.grow(glm::vec3(-kRoomX, 0.0f, -kRoomZ));
  b.grow(glm::vec3(kRoomX, kRoomY, kRoomZ));
  return b;
}

Scene makeClutter(uint32_t triangles, uint32_t seed) {
  Scene scene;
  scene.name = std::string(kClutterName) + ":" + std::to_string(triangles);
  scene.skyColor = glm::vec3(0.9f, 1.0f, 1.2f);  // the window's sky
  scene.viewpoints = clutterViews();
  MeshBuilder b(scene);
  const ClutterMaterials m = addClutterMaterials(b);
  SplitMixRng rng(seed);
  clutterRoom(b, m);
  clutterShelves(b, rng, m);
  ClutterPlacement placement;
  for (const Viewpoint& v : scene.viewpoints) placement.cameras.push_back(v.position);
  // Loose objects, one kind after another at random, until the budget is spent; a spot near a camera is
  // drawn again (the draws stay in the one sequence, so the scene still follows from N alone).
  while (scene.triangles.size() < triangles) {
    const uint64_t kind = rng.next() % 10;
    const glm::vec3 p = clutterFloorSpot(rng);
    if (!placement.free(p, kind >= 8 ? 0.2f : 1.2f)) continue;
    const size_t first = scene.triangles.size();
    if (kind < 1) clutterTable(b, rng, m, p);
    else if (kind < 2) clutterChair(b, rng, m, p);
    else if (kind < 6) pottedPlant(b, rng, m, p, scene, triangles);
    else if (kind < 8) boxPile(b, rng, m, p);
    else hangingCable(b, rng, m, p);
    clutterKeepInside(scene, first);
  }
  return scene;
}

}  // namespace raylab
