// The built-in scenes: geometry sanity (finite, non-degenerate, closed solids), determinism of the
// temple's seed, and, with a brute-force CPU ray caster, that each temple viewpoint shows what it is
// for (alley: nearly all hits, hall: no sky and no leaks, openings: much sky).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <tuple>

#include "scenes/procedural.h"
#include "tests/scene_checks.h"

namespace raylab {
namespace {

float hitFraction(const Scene& s, const char* viewpoint, int width = 48, int height = 24) {
  const Viewpoint* v = s.findViewpoint(viewpoint);
  EXPECT_NE(v, nullptr) << viewpoint;
  if (v == nullptr) return 0.0f;
  std::vector<glm::vec3> rays = cameraRays(*v, width, height);
  int hits = 0;
  for (const glm::vec3& d : rays) hits += castRay(s, v->position, d) < kMiss;
  return static_cast<float>(hits) / static_cast<float>(rays.size());
}

float doubleArea(const Triangle& t) { return glm::length(glm::cross(t.v[1] - t.v[0], t.v[2] - t.v[0])); }

TEST(Temple, ViewpointsAreNamedAndOrdered) {
  Scene s = makeTemple();
  ASSERT_GE(s.viewpoints.size(), 4u);
  EXPECT_EQ(s.viewpoints[0].name, "overview");  // the default: bright from the first samples
  EXPECT_EQ(s.viewpoints[1].name, "alley");
  EXPECT_EQ(s.viewpoints[2].name, "hall");
  EXPECT_EQ(s.viewpoints[3].name, "openings");
  EXPECT_EQ(s.name, "temple");
}

TEST(Temple, TrianglesAreFiniteNonDegenerateAndUseValidMaterials) {
  Scene s = makeTemple();
  EXPECT_GE(s.triangles.size(), 3000u);
  EXPECT_LE(s.triangles.size(), 60000u);
  for (const Triangle& t : s.triangles) {
    for (const glm::vec3& v : t.v)
      ASSERT_TRUE(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z));
    float longest =
        std::max({glm::length(t.v[1] - t.v[0]), glm::length(t.v[2] - t.v[1]), glm::length(t.v[0] - t.v[2])});
    ASSERT_GT(doubleArea(t), 1e-5f * longest * longest);
    ASSERT_LT(t.material, s.materials.size());
  }
}

TEST(Temple, BoundsHaveTheIntendedSize) {
  glm::vec3 e = makeTemple().bounds().extent();
  EXPECT_NEAR(e.x, 150.0f, 10.0f);
  EXPECT_NEAR(e.z, 150.0f, 10.0f);
  EXPECT_NEAR(e.y, 40.0f, 5.0f);
  Scene big = makeTemple({.size = 2.0f});
  EXPECT_NEAR(big.bounds().extent().x, 2.0f * e.x, 1e-3f);
  EXPECT_EQ(big.findViewpoint("hall")->position, 2.0f * makeTemple().findViewpoint("hall")->position);
}

TEST(Temple, IsOpenToTheSkyAndHasLamps) {
  Scene s = makeTemple();
  EXPECT_GT(s.skyColor.x + s.skyColor.y + s.skyColor.z, 0.0f);
  int lampTriangles = 0;
  for (const Triangle& t : s.triangles) {
    const Material& m = s.materials[t.material];
    if (!m.isEmissive()) continue;
    ++lampTriangles;
    float peak = std::max({m.emissive.x, m.emissive.y, m.emissive.z});
    EXPECT_GE(peak, 5.0f);
    EXPECT_LE(peak, 20.0f);
  }
  EXPECT_GE(lampTriangles, 12 * 5);  // at least five lamp boxes
  int metallic = 0, distinctDiffuse = 0;
  for (const Material& m : s.materials) {
    metallic += m.metallic > 0.5f;
    distinctDiffuse += !m.isEmissive() && m.metallic < 0.5f;
  }
  EXPECT_GE(metallic, 1);
  EXPECT_GE(distinctDiffuse, 3);
}

TEST(Temple, SolidsAreClosedAndWoundOutwards) {
  Scene s = makeTemple();
  expectEdgesPaired(s);
  EXPECT_GT(signedVolume(s), 0.0f);
}

TEST(Temple, SeedIsDeterministicAndChangesGeometry) {
  Scene a = makeTemple({.seed = 7}), b = makeTemple({.seed = 7}), c = makeTemple({.seed = 8});
  EXPECT_EQ(triangleBytes(a), triangleBytes(b));
  EXPECT_NE(triangleBytes(a), triangleBytes(c));
  expectEdgesPaired(c);
}

TEST(Temple, ParametersChangeDetailAndColumns) {
  size_t base = makeTemple().triangles.size();
  EXPECT_GT(makeTemple({.detail = 2}).triangles.size(), base);
  EXPECT_GT(makeTemple({.columnsPerSide = 12}).triangles.size(), base);
  expectEdgesPaired(makeTemple({.seed = 3, .columnsPerSide = 5, .detail = 2}));
}

TEST(Temple, AlleyViewRaysNearlyAllHit) {
  float hits = hitFraction(makeTemple(), "alley");
  EXPECT_GE(hits, 0.97f);
  RecordProperty("alley_hit_fraction", std::to_string(hits));
}

TEST(Temple, OpeningsViewSeesMuchSky) {
  float hits = hitFraction(makeTemple(), "openings");
  RecordProperty("openings_hit_fraction", std::to_string(hits));
  EXPECT_LE(hits, 0.6f);
  EXPECT_GE(hits, 0.05f);  // but not only sky
}

TEST(Temple, HallViewSeesOnlyTheHallInterior) {
  Scene s = makeTemple();
  const Viewpoint* v = s.findViewpoint("hall");
  ASSERT_NE(v, nullptr);
  for (const glm::vec3& d : cameraRays(*v, 48, 24)) {
    float t = castRay(s, v->position, d);
    ASSERT_LT(t, kMiss);
    glm::vec3 p = v->position + t * d;  // inside the hall's outer walls and under its roof
    EXPECT_TRUE(p.x > -36 && p.x < 36 && p.z > -70 && p.z < -24 && p.y < 19.5f)
        << p.x << " " << p.y << " " << p.z;
  }
}

// Rays from inside the hall leave only through the openings of its north wall: no cracks.
TEST(Temple, HallIsLightTightButForItsOpenings) {
  Scene s = makeTemple();
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  int escaped = 0;
  for (glm::vec3 origin : {glm::vec3(0, 4, -29), glm::vec3(-25, 2, -50), glm::vec3(20, 12, -65)}) {
    for (int i = 0; i < 400; ++i) {
      glm::vec3 d(u(rng), u(rng), u(rng));
      if (glm::length(d) < 0.1f || glm::length(d) > 1.0f) continue;
      d = glm::normalize(d);
      if (castRay(s, origin, d) < kMiss) continue;
      ++escaped;
      ASSERT_GT(d.z, 0.0f);
      glm::vec3 p = origin + ((-25.0f - origin.z) / d.z) * d;  // crossing the north wall's mid-plane
      bool door = std::fabs(p.x) < 3 && p.y < 7;
      bool window = p.y > 5 && p.y < 11 && std::fabs(p.x) > 10 && std::fabs(p.x) < 26 &&
                    !(std::fabs(p.x) > 16 && std::fabs(p.x) < 20);
      EXPECT_TRUE(door || window) << "leak at " << p.x << " " << p.y;
    }
  }
  EXPECT_GT(escaped, 0);  // the openings exist
}

TEST(Cornell, IsTheClassicBox) {
  Scene s = makeCornell();
  EXPECT_EQ(s.skyColor, glm::vec3(0.0f));
  ASSERT_NE(s.findViewpoint("front"), nullptr);
  EXPECT_EQ(s.viewpoints[0].name, "front");
  int emissive = 0;
  for (const Material& m : s.materials) emissive += m.isEmissive();
  EXPECT_EQ(emissive, 1);
  EXPECT_EQ(s.triangles.size(), 5u * 2 + 2 + 2 * 12);  // walls, light, two blocks
  for (const Triangle& t : s.triangles) EXPECT_GT(doubleArea(t), 1e-4f);
  // Red on the image's left (+x, seen from -z), green on the right.
  const Viewpoint& v = s.viewpoints[0];
  glm::vec3 f = glm::normalize(v.target - v.position), right = glm::cross(f, v.up);
  auto colorAt = [&](float side) {
    Hit h = nearestHit(s, v.position, glm::normalize(f + side * 0.3f * right));
    return h.t < kMiss ? s.materials[s.triangles[h.triangle].material].name : std::string("sky");
  };
  EXPECT_EQ(colorAt(-1.0f), "red");
  EXPECT_EQ(colorAt(1.0f), "green");
  float hits = hitFraction(s, "front", 32, 32);  // the classic square image
  EXPECT_LT(hits, 1.0f);  // the front is open and the frame a little wider than the box
  EXPECT_GT(hits, 0.85f);
}

TEST(Furnace, IsAClosedUnitSphereOfOneLambertMaterial) {
  Scene s = makeFurnace(0.3f, 2.0f, 3);
  EXPECT_EQ(s.triangles.size(), 20u * 64u);
  ASSERT_EQ(s.materials.size(), 1u);
  const Material& m = s.materials[0];
  EXPECT_EQ(m.baseColor, glm::vec3(0.3f));
  EXPECT_EQ(m.emissive, glm::vec3(2.0f));
  EXPECT_EQ(m.metallic, 0.0f);
  EXPECT_EQ(m.roughness, 1.0f);
  EXPECT_EQ(m.specularWeight, 0.0f);
  EXPECT_EQ(s.skyColor, glm::vec3(0.0f));
  for (const Triangle& t : s.triangles) {
    EXPECT_EQ(t.material, 0u);
    for (const glm::vec3& v : t.v) EXPECT_NEAR(glm::length(v), 1.0f, 1e-5f);
  }
  // Closed: every undirected edge belongs to exactly two triangles, and the winding is consistent.
  using Key = std::tuple<float, float, float>;
  std::map<std::pair<Key, Key>, int> uses;
  for (const Triangle& t : s.triangles)
    for (int i = 0; i < 3; ++i) {
      Key a{t.v[i].x, t.v[i].y, t.v[i].z}, b{t.v[(i + 1) % 3].x, t.v[(i + 1) % 3].y, t.v[(i + 1) % 3].z};
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  EXPECT_EQ(uses.size(), s.triangles.size() * 3 / 2);
  for (const auto& [edge, n] : uses) ASSERT_EQ(n, 2);
  expectEdgesPaired(s);
  EXPECT_GT(signedVolume(s), 0.0f);  // outward
  ASSERT_NE(s.findViewpoint("center"), nullptr);
  EXPECT_EQ(s.viewpoints[0].position, glm::vec3(0.0f));
  EXPECT_NEAR(s.viewpoints[0].yfovRadians, 1.0f, 1e-6f);
  EXPECT_EQ(hitFraction(s, "center"), 1.0f);
  EXPECT_EQ(makeFurnace().triangles.size(), 1280u);
  EXPECT_EQ(makeFurnace(0.5f, 0.5f, 1).triangles.size(), 80u);
}

}  // namespace
}  // namespace raylab
