// The scene-scale family temple-detail:N: the triangle count follows N, the same N builds the same
// triangles, the added detail is closed and lies in the hall where the hall view sees it, and names with a
// bad size are refused with the accepted range.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "scenes/procedural.h"
#include "scenes/scene_library.h"
#include "scenes/temple_detail.h"
#include "scenes/temple_layout.h"
#include "tests/scene_checks.h"

namespace raylab {
namespace {

TEST(TempleDetail, TriangleCountFollowsTheAskedSize) {
  size_t previous = 0;
  for (uint32_t n : {10000u, 20000u, 50000u, 120000u, 400000u}) {
    size_t got = makeTempleDetail(n).triangles.size();
    RecordProperty("triangles_" + std::to_string(n), std::to_string(got));
    EXPECT_NEAR(static_cast<double>(got), static_cast<double>(n), 0.01 * n) << "temple-detail:" << n;
    EXPECT_GT(got, previous) << "temple-detail:" << n << " is not larger than the size before it";
    previous = got;
  }
}

TEST(TempleDetail, SameSizeSameTrianglesAndOtherSizeOtherTriangles) {
  Scene a = makeTempleDetail(30000), b = makeTempleDetail(30000), c = makeTempleDetail(31000);
  EXPECT_EQ(triangleBytes(a), triangleBytes(b));
  EXPECT_NE(triangleBytes(a), triangleBytes(c));
  EXPECT_EQ(a.name, "temple-detail:30000");
}

TEST(TempleDetail, ExtendsTheTempleWithClosedSolids) {
  Scene temple = makeTemple(), detail = makeTempleDetail(20000);
  ASSERT_GT(detail.triangles.size(), temple.triangles.size());
  // The temple comes first, unchanged; what follows is the detail.
  Scene prefix = detail;
  prefix.triangles.resize(temple.triangles.size());
  EXPECT_EQ(triangleBytes(prefix), triangleBytes(temple));
  expectEdgesPaired(detail);
  EXPECT_GT(signedVolume(detail), signedVolume(temple));
  EXPECT_EQ(detail.materials.size(), temple.materials.size());
}

TEST(TempleDetail, DetailStaysInsideTheHall) {
  namespace hall = temple_layout;
  Scene temple = makeTemple(), detail = makeTempleDetail(50000);
  for (size_t i = temple.triangles.size(); i < detail.triangles.size(); ++i)
    for (const glm::vec3& v : detail.triangles[i].v) {
      ASSERT_TRUE(v.x > hall::kHallInnerWest - 0.1f && v.x < hall::kHallInnerEast + 0.1f) << v.x;
      ASSERT_TRUE(v.z > hall::kHallInnerSouth - 0.1f && v.z < hall::kHallInnerNorth + 0.1f) << v.z;
      ASSERT_TRUE(v.y > -1.0f && v.y < hall::kHallWallTop) << v.y;  // boulders sink into the ground (y >= -1)
    }
}

// The hall view is the default and looks at the detail: over a third of its primary rays end on it (the rest
// on the roof, the dais and the lamps; 45% at this writing).
TEST(TempleDetail, HallViewIsTheDefaultAndSeesTheDetail) {
  Scene detail = makeTempleDetail(10000);
  size_t templeTriangles = makeTemple().triangles.size();
  ASSERT_FALSE(detail.viewpoints.empty());
  const Viewpoint& v = detail.viewpoints.front();
  EXPECT_EQ(v.name, "hall");
  EXPECT_EQ(detail.viewpointList(), "hall, overview, alley, openings");
  int onDetail = 0, rays = 0;
  for (const glm::vec3& d : cameraRays(v, 32, 16)) {
    Hit h = nearestHit(detail, v.position, d);
    ASSERT_LT(h.t, kMiss) << "the hall view sees the sky";
    onDetail += h.triangle >= templeTriangles;
    ++rays;
  }
  RecordProperty("hall_rays_on_detail", std::to_string(onDetail) + "/" + std::to_string(rays));
  EXPECT_GT(onDetail, rays / 3);
}

TEST(TempleDetail, NamesAndSizes) {
  EXPECT_TRUE(isTempleDetailName("temple-detail"));
  EXPECT_TRUE(isTempleDetailName("temple-detail:xyz"));
  EXPECT_FALSE(isTempleDetailName("temple"));
  EXPECT_FALSE(isTempleDetailName("temple-details"));
  EXPECT_EQ(parseTempleDetailTriangles("temple-detail"), kTempleDetailDefaultTriangles);
  EXPECT_EQ(parseTempleDetailTriangles("temple-detail:1e6"), 1000000u);
  EXPECT_EQ(parseTempleDetailTriangles("temple-detail:2500000"), 2500000u);
  EXPECT_EQ(parseTempleDetailTriangles("temple-detail:1e4"), kTempleDetailMinTriangles);
  EXPECT_EQ(parseTempleDetailTriangles("temple-detail:3e7"), kTempleDetailMaxTriangles);
  for (const char* bad : {"temple-detail:", "temple-detail:abc", "temple-detail:9999", "temple-detail:3.1e7",
                          "temple-detail:-1e6", "temple-detail:nan", "temple-detail:inf", "temple-detail:1e6x",
                          "temple-detail:1e400"}) {
    try {
      parseTempleDetailTriangles(bad);
      ADD_FAILURE() << bad << " was accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("1e4) to 30000000 (3e7)"), std::string::npos) << e.what();
    }
    EXPECT_THROW(checkSceneName(bad), std::invalid_argument) << bad;
    EXPECT_THROW(loadSceneByName(bad), std::invalid_argument) << bad;
  }
  EXPECT_EQ(loadSceneByName("temple-detail:1e4").triangles.size(), makeTempleDetail(10000).triangles.size());
}

}  // namespace
}  // namespace raylab
