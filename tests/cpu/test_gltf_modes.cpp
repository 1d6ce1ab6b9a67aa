// glTF triangle strips and fans (modes 5 and 6) in every index form, against triangle lists written out by
// hand from the specification's formulas; points and lines are refused naming their mode. The fixtures in
// tests/data/modes are planar and counter-clockwise from +z (make_fixtures.py), so a preserved winding
// shows as every triangle facing +z.
#include <gtest/gtest.h>

#include "scenes/gltf_loader.h"
#include "scenes/primitive_modes.h"

namespace raylab {
namespace {

const std::string kModes = RAYLAB_SOURCE_DIR "/tests/data/modes/";

using Tri = std::array<glm::vec3, 3>;

// The fixtures' vertices (make_fixtures.py STRIP and FAN).
const glm::vec3 S[] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 2, 0}, {1, 2, 0}};
const glm::vec3 F[] = {{0, 0, 0}, {2, 0, 0}, {1.5f, 1.5f, 0}, {0, 2, 0}, {-1.5f, 1.5f, 0}, {-2, 0, 0}};

// p_i = (v_i, v_{i+1+i%2}, v_{i+2-i%2}) and p_i = (v_{i+1}, v_{i+2}, v_0), written out.
const std::vector<Tri> kStrip = {{S[0], S[1], S[2]}, {S[1], S[3], S[2]}, {S[2], S[3], S[4]}, {S[3], S[5], S[4]}};
const std::vector<Tri> kFan = {{F[1], F[2], F[0]}, {F[2], F[3], F[0]}, {F[3], F[4], F[0]}, {F[4], F[5], F[0]}};

std::vector<Tri> trianglesOf(const Scene& s) {
  std::vector<Tri> out;
  for (const Triangle& t : s.triangles) out.push_back({t.v[0], t.v[1], t.v[2]});
  return out;
}

TEST(GltfModes, StripAndFanIndexLists) {
  const std::vector<uint32_t> six = {10, 11, 12, 13, 14, 15};
  EXPECT_EQ(triangleListIndices(kModeTriangleStrip, six),
            (std::vector<uint32_t>{10, 11, 12, 11, 13, 12, 12, 13, 14, 13, 15, 14}));
  EXPECT_EQ(triangleListIndices(kModeTriangleFan, six),
            (std::vector<uint32_t>{11, 12, 10, 12, 13, 10, 13, 14, 10, 14, 15, 10}));
  EXPECT_EQ(triangleListIndices(kModeTriangles, {0, 1, 2, 3, 4}), (std::vector<uint32_t>{0, 1, 2}));
  // Degenerate joins of two strips vanish; the triangles after them keep the parity of their position
  // (triangle 5 is odd: (v5, v7, v6)).
  EXPECT_EQ(triangleListIndices(kModeTriangleStrip, {0, 1, 2, 2, 5, 5, 6, 7}),
            (std::vector<uint32_t>{0, 1, 2, 5, 7, 6}));
  EXPECT_TRUE(triangleListIndices(kModeTriangleStrip, {0, 1}).empty());
  EXPECT_TRUE(triangleListIndices(kModeTriangleFan, {}).empty());
  EXPECT_TRUE(triangleListIndices(kModeLines, six).empty());
  EXPECT_EQ(primitiveModeName(kModeTriangleFan), "TRIANGLE_FAN");
  EXPECT_EQ(primitiveModeName(7), "");
}

class GltfModeFile : public ::testing::TestWithParam<std::string> {};

TEST_P(GltfModeFile, StripAndFanLoadAsTheirTriangles) {
  for (const char* shape : {"strip", "fan"}) {
    std::string file = kModes + shape + "_" + GetParam() + ".gltf";
    Scene scene;
    ASSERT_NO_THROW(scene = loadGltf(file)) << file;
    EXPECT_EQ(trianglesOf(scene), std::string(shape) == "strip" ? kStrip : kFan) << file;
    for (const Triangle& t : scene.triangles) {
      glm::vec3 n = glm::cross(t.v[1] - t.v[0], t.v[2] - t.v[0]);
      EXPECT_GT(n.z, 0.0f) << file << ": a triangle's winding was flipped";
    }
    EXPECT_TRUE(scene.loadWarnings.empty()) << file << ": " << scene.loadWarnings.front();
  }
}

INSTANTIATE_TEST_SUITE_P(IndexForms, GltfModeFile, ::testing::Values("none", "u8", "u16", "u32"));

TEST(GltfModes, PointsAndLinesAreRefusedByName) {
  const std::pair<const char*, const char*> cases[] = {
      {"points", "POINTS (0)"}, {"lines", "LINES (1)"}, {"line_loop", "LINE_LOOP (2)"}, {"line_strip", "LINE_STRIP (3)"}};
  for (const auto& [file, mode] : cases) {
    try {
      loadGltf(kModes + file + ".gltf");
      ADD_FAILURE() << file << " loaded";
    } catch (const SceneLoadError& e) {
      std::string m = e.what();
      EXPECT_NE(m.find("no triangles"), std::string::npos) << m;
      EXPECT_NE(m.find(mode), std::string::npos) << m;
    }
  }
}

}  // namespace
}  // namespace raylab
