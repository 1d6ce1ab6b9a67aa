// The cluttered store room clutter:N: the triangle count follows N, the same N builds the same triangles,
// everything lies in the room (walls included), every camera stands in the room's free air and sees the
// clutter, the room has its lights and window, and names with a bad size are refused with the range.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

#include "scenes/clutter.h"
#include "scenes/scene_library.h"
#include "tests/scene_checks.h"

namespace raylab {
namespace {

TEST(Clutter, TriangleCountFollowsTheAskedSize) {
  size_t previous = 0;
  for (uint32_t n : {50000u, 100000u, 300000u, 1000000u}) {
    const size_t got = makeClutter(n).triangles.size();
    RecordProperty("triangles_" + std::to_string(n), std::to_string(got));
    EXPECT_NEAR(static_cast<double>(got), static_cast<double>(n), 0.05 * n) << "clutter:" << n;
    EXPECT_GE(got, n) << "clutter:" << n;  // filled until the budget is reached
    EXPECT_GT(got, previous);
    previous = got;
  }
}

TEST(Clutter, SameSizeSameTrianglesAndOtherSizeMoreOfThem) {
  const Scene a = makeClutter(60000), b = makeClutter(60000), c = makeClutter(70000);
  EXPECT_EQ(triangleBytes(a), triangleBytes(b));
  EXPECT_NE(triangleBytes(a), triangleBytes(c));
  EXPECT_EQ(a.name, "clutter:60000");
  // A larger room is the smaller one with more loose objects: the same sequence, drawn further.
  ASSERT_GT(c.triangles.size(), a.triangles.size());
  EXPECT_EQ(std::memcmp(a.triangles.data(), c.triangles.data(), (a.triangles.size() - 200) * sizeof(Triangle)), 0);
}

// Settings::clutterSeed (--clutter-seed) lays the room out: the default seed is the room of before, another
// seed other places, through the scene's name as every mode loads it.
TEST(Clutter, TheSeedLaysOutTheRoom) {
  const Scene a = makeClutter(60000), b = loadSceneByName("clutter:60000", kClutterDefaultSeed);
  const Scene c = loadSceneByName("clutter:60000", 7), d = makeClutter(60000, 7);
  EXPECT_EQ(triangleBytes(a), triangleBytes(b));
  EXPECT_EQ(triangleBytes(c), triangleBytes(d));
  EXPECT_NE(triangleBytes(a), triangleBytes(c));
  EXPECT_GE(c.triangles.size(), 60000u);
  const Bounds inside = clutterRoomInterior(), all = c.bounds();
  for (int a = 0; a < 3; ++a) {  // still within the walls, 0.2 thick
    EXPECT_GE(all.min[a], inside.min[a] - 0.2f - 1e-4f) << "axis " << a;
    EXPECT_LE(all.max[a], inside.max[a] + 0.2f + 1e-4f) << "axis " << a;
  }
}

TEST(Clutter, EverythingLiesInTheRoomAndItsWalls) {
  const Scene s = makeClutter(100000);
  const Bounds inside = clutterRoomInterior();
  const Bounds all = s.bounds();
  for (int a = 0; a < 3; ++a) {
    // The walls, floor and ceiling are 0.2 thick around the interior; nothing pokes out of them.
    EXPECT_GE(all.min[a], inside.min[a] - 0.2f - 1e-4f) << "axis " << a;
    EXPECT_LE(all.max[a], inside.max[a] + 0.2f + 1e-4f) << "axis " << a;
    EXPECT_LT(all.min[a], inside.min[a]);  // the room is closed around the interior
    EXPECT_GT(all.max[a], inside.max[a]);
  }
  // The loose objects lie in the interior: the room and its shelves come first (about 22,500 triangles), so
  // every triangle from half of clutter:5e4 on is a loose object's.
  const Scene bare = makeClutter(50000), more = makeClutter(100000);
  size_t outside = 0;
  for (size_t i = bare.triangles.size() / 2; i < more.triangles.size(); ++i)
    for (const glm::vec3& v : more.triangles[i].v)
      for (int a = 0; a < 3; ++a) outside += v[a] < inside.min[a] - 1e-4f || v[a] > inside.max[a] + 1e-4f;
  EXPECT_EQ(outside, 0u);
  const glm::vec3 extent = inside.extent();
  EXPECT_NEAR(extent.x, 14.0f, 1e-4f);
  EXPECT_NEAR(extent.z, 10.0f, 1e-4f);
}

TEST(Clutter, LightsAWindowAndThreeViews) {
  const Scene s = makeClutter(50000);
  int emissive = 0;
  for (const Material& m : s.materials) emissive += m.isEmissive();
  EXPECT_EQ(emissive, 1);
  EXPECT_GT(s.skyColor.x + s.skyColor.y + s.skyColor.z, 0.0f) << "the window lets the sky in";
  ASSERT_EQ(s.viewpoints.size(), 3u);
  EXPECT_EQ(s.viewpoints[0].name, "overview");
  EXPECT_EQ(s.viewpoints[1].name, "shelves");
  EXPECT_EQ(s.viewpoints[2].name, "floor");
}

TEST(Clutter, CamerasStandInFreeAirAndSeeTheClutter) {
  const Scene s = makeClutter(50000);
  const Bounds inside = clutterRoomInterior();
  for (const Viewpoint& v : s.viewpoints) {
    for (int a = 0; a < 3; ++a) {
      EXPECT_GT(v.position[a], inside.min[a]) << v.name;
      EXPECT_LT(v.position[a], inside.max[a]) << v.name;
    }
    // Rays of a coarse 8x4 camera all hit the room (it is closed but for the window, which no view faces
    // head on), none within 0.3 m (the camera is not inside an object), and not all at one distance.
    float nearest = kMiss, farthest = 0.0f;
    int hits = 0;
    for (const glm::vec3& d : cameraRays(v, 8, 4)) {
      const float t = castRay(s, v.position, d);
      if (t == kMiss) continue;
      ++hits;
      nearest = std::min(nearest, t);
      farthest = std::max(farthest, t);
    }
    EXPECT_GE(hits, 30) << v.name;
    EXPECT_GT(nearest, 0.3f) << v.name;
    EXPECT_GT(farthest, 2.0f * nearest) << v.name;
  }
}

TEST(Clutter, NamesAndSizes) {
  EXPECT_EQ(parseClutterTriangles("clutter"), kClutterDefaultTriangles);
  EXPECT_EQ(parseClutterTriangles("clutter:1e5"), 100000u);
  EXPECT_EQ(parseClutterTriangles("clutter:250000"), 250000u);
  EXPECT_TRUE(isClutterName("clutter:x"));
  EXPECT_FALSE(isClutterName("clutters"));
  for (const char* bad : {"clutter:1e4", "clutter:4e6", "clutter:", "clutter:many", "clutter:1e5x"}) {
    try {
      parseClutterTriangles(bad);
      ADD_FAILURE() << bad << " was accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("from 50000 (5e4) to 3000000 (3e6)"), std::string::npos) << e.what();
    }
  }
  EXPECT_NO_THROW(checkSceneName("clutter:2e5"));
  EXPECT_THROW(checkSceneName("clutter:9"), std::invalid_argument);
}

}  // namespace
}  // namespace raylab
