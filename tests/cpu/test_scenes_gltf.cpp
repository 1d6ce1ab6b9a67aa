// The glTF loader: every malformed fixture (tests/data/malformed, made by tests/data/make_fixtures.py)
// must fail with a SceneLoadError that names the file and the defect; the valid fixture and the
// shared real-world scenes must load with the expected triangles, materials and viewpoints.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <set>
#include <stdexcept>
#include <string>

#include "scenes/gltf_loader.h"
#include "scenes/procedural.h"
#include "scenes/scene_library.h"

namespace raylab {
namespace {

namespace fs = std::filesystem;

const std::string kData = RAYLAB_SOURCE_DIR "/tests/data/";
const std::string kShared = RAYLAB_SOURCE_DIR "/../shared/scenes/";

// Each malformed fixture and a fragment its message must contain, so the test fails if the file is
// rejected for some other reason than the defect it was made for.
struct Malformed {
  const char* file;
  const char* fragment;
};

const Malformed kMalformed[] = {
    {"index_out_of_range.gltf", "index 5 at position 2 out of range (POSITION has 3 vertices)"},
    {"accessor_out_of_range.gltf", "accessor 7 (POSITION of mesh 'tri' primitive 0): out of range"},
    {"bufferview_out_of_range.gltf",
     "accessor 0 (POSITION of mesh 'tri' primitive 0): bufferView 12 out of range (file has 3)"},
    {"missing_bin.gltf", "missing_bin.bin"},
    {"node_cycle.gltf", "cycle in the node hierarchy"},
    {"node_child_out_of_range.gltf", "child 5 out of range"},
    {"truncated.glb", "Invalid glTF binary"},
    {"truncated_header.glb", "Too short"},
    {"position_vec2.gltf", "type VEC2, expected VEC3"},
    {"position_unsigned_short.gltf", "component type UNSIGNED_SHORT, expected FLOAT"},
    {"accessor_past_bufferview.gltf", "read past the end of bufferView 0"},
    {"material_out_of_range.gltf", "material 3 out of range (file has 1)"},
    {"invalid_json.gltf", "parse error"},
    {"buffer_out_of_range.gltf", "buffer 2 out of range"},
    {"bufferview_past_buffer.gltf", "exceed buffer 0"},
    {"accessor_offset_past_bufferview.gltf", "read past the end of bufferView 2"},
    {"stride_too_small.gltf", "byteStride 4"},
    {"indices_float.gltf", "component type FLOAT"},
    {"texcoord_count_mismatch.gltf", "2 elements, but POSITION has 3"},
    {"mesh_out_of_range.gltf", "mesh 3 out of range"},
    {"camera_out_of_range.gltf", "camera 2 out of range"},
    {"scene_node_out_of_range.gltf", "node 9 out of range"},
    {"default_scene_out_of_range.gltf", "default scene 4 out of range"},
    {"texture_out_of_range.gltf", "texture 4 out of range"},
    {"image_out_of_range.gltf", "image 2 out of range"},
    {"nan_position.gltf", "element 1 is not finite"},
    {"sparse_accessor.gltf", "sparse accessors are not supported"},
    {"no_triangles.gltf", "no triangles"},
};

class MalformedGltf : public testing::TestWithParam<Malformed> {};

TEST_P(MalformedGltf, ThrowsSceneLoadErrorNamingFileAndDefect) {
  std::string path = kData + "malformed/" + GetParam().file;
  ASSERT_TRUE(fs::exists(path)) << path;
  for (bool viaLibrary : {false, true}) {
    try {
      if (viaLibrary)
        loadSceneByName(path);
      else
        loadGltf(path);
      ADD_FAILURE() << path << " loaded without error";
    } catch (const SceneLoadError& e) {
      std::string message = e.what();
      EXPECT_NE(message.find(GetParam().file), std::string::npos) << message;
      EXPECT_NE(message.find(GetParam().fragment), std::string::npos) << message;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Fixtures, MalformedGltf, testing::ValuesIn(kMalformed),
                         [](const testing::TestParamInfo<Malformed>& info) {
                           std::string name = fs::path(info.param.file).stem().string();
                           name += fs::path(info.param.file).extension() == ".glb" ? "_glb" : "";
                           return name;
                         });

// A fixture added to the folder but not to the list above would go untested.
TEST(MalformedGltfFixtures, EveryFileIsListed) {
  std::set<std::string> listed;
  for (const Malformed& m : kMalformed) listed.insert(m.file);
  size_t files = 0;
  for (const fs::directory_entry& e : fs::directory_iterator(kData + "malformed")) {
    ++files;
    EXPECT_TRUE(listed.count(e.path().filename().string())) << e.path();
  }
  EXPECT_EQ(files, listed.size());
}

void expectValidTriangle(const Scene& s) {
  ASSERT_EQ(s.triangles.size(), 1u);
  const Triangle& t = s.triangles[0];
  EXPECT_EQ(t.v[0], glm::vec3(0, 0, 0));
  EXPECT_EQ(t.v[1], glm::vec3(1, 0, 0));
  EXPECT_EQ(t.v[2], glm::vec3(0, 1, 0));
  EXPECT_EQ(t.uv[1], glm::vec2(1, 0));
  EXPECT_EQ(t.uv[2], glm::vec2(0, 1));
  ASSERT_LT(t.material, s.materials.size());
  const Material& m = s.materials[t.material];
  EXPECT_EQ(m.name, "orange");
  EXPECT_EQ(m.baseColor, glm::vec3(1.0f, 0.5f, 0.25f));
  EXPECT_EQ(m.metallic, 0.0f);
  EXPECT_EQ(m.roughness, 0.5f);
  EXPECT_EQ(m.emissive, glm::vec3(2.0f, 1.0f, 0.0f));  // emissiveFactor times KHR_materials_emissive_strength
  EXPECT_EQ(m.baseColorTexture, -1);
  EXPECT_EQ(s.skyColor, glm::vec3(1.0f));
  EXPECT_EQ(s.name, "valid_triangle");

  ASSERT_EQ(s.viewpoints.size(), 2u);
  const Viewpoint& cam = s.viewpoints[0];
  EXPECT_EQ(cam.name, "Cam");
  EXPECT_NEAR(glm::length(cam.position - glm::vec3(0.3f, 0.3f, 2.0f)), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::length(glm::normalize(cam.target - cam.position) - glm::vec3(0, 0, -1)), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::length(cam.up - glm::vec3(0, 1, 0)), 0.0f, 1e-6f);
  EXPECT_NEAR(cam.yfovRadians, 0.7f, 1e-6f);

  // The computed default view sees every vertex.
  const Viewpoint& d = s.viewpoints[1];
  EXPECT_EQ(d.name, "default");
  glm::vec3 forward = glm::normalize(d.target - d.position);
  for (const glm::vec3& v : t.v)
    EXPECT_LT(std::acos(glm::dot(glm::normalize(v - d.position), forward)), 0.5f * d.yfovRadians);
}

TEST(ValidGltf, TriangleLoadsWithMaterialAndCamera) {
  expectValidTriangle(loadGltf(kData + "valid_triangle.gltf"));
}

TEST(ValidGltf, GlbContainerLoadsTheSame) { expectValidTriangle(loadGltf(kData + "valid_triangle.glb")); }

// Transforms (TRS, matrix, parent times child), instancing, mirroring, and the parts that are skipped.
TEST(ValidGltf, HierarchyIsFlattenedWithWorldTransforms) {
  Scene s = loadGltf(kData + "hierarchy.gltf");
  // Three instances of one triangle; the 4th index and the LINES primitive are ignored.
  ASSERT_EQ(s.triangles.size(), 3u);
  // ... and said so, in the warnings the window's scene panel lists.
  ASSERT_EQ(s.loadWarnings.size(), 2u);
  EXPECT_NE(s.loadWarnings[0].find("not a multiple of 3"), std::string::npos) << s.loadWarnings[0];
  EXPECT_NE(s.loadWarnings[1].find("LINES (1)"), std::string::npos) << s.loadWarnings[1];
  auto near = [](const glm::vec3& a, const glm::vec3& b) { return glm::length(a - b) < 1e-5f; };
  // "turned": translate (10,0,0) * rotate 90 degrees about +y * scale 2.
  const Triangle& turned = s.triangles[0];
  EXPECT_TRUE(near(turned.v[0], {10, 0, 0}));
  EXPECT_TRUE(near(turned.v[1], {10, 0, -2}));
  EXPECT_TRUE(near(turned.v[2], {10, 2, 0}));
  // "lifted", its child: the parent's transform after its own translation (0,5,0).
  EXPECT_TRUE(near(s.triangles[1].v[0], {10, 10, 0}));
  EXPECT_TRUE(near(s.triangles[1].v[1], {10, 10, -2}));
  // "mirrored" (scale -1 in x): same front face (+z normal), so its winding was swapped.
  const Triangle& m = s.triangles[2];
  glm::vec3 normal = glm::cross(m.v[1] - m.v[0], m.v[2] - m.v[0]);
  EXPECT_GT(normal.z, 0.0f);
  EXPECT_TRUE(near(m.v[0], {0, 0, 0}));
  // No material in the file: the lab's default grey diffuse.
  for (const Triangle& t : s.triangles) {
    ASSERT_LT(t.material, s.materials.size());
    EXPECT_EQ(s.materials[t.material].name, "default");
    EXPECT_EQ(s.materials[t.material].metallic, 0.0f);
  }
  ASSERT_EQ(s.viewpoints.size(), 1u);
  EXPECT_EQ(s.viewpoints[0].name, "default");
}

TEST(SceneLibrary, NamesAndPaths) {
  EXPECT_EQ(builtinSceneNames(), (std::vector<std::string>{"temple", "cornell", "furnace", "temple-detail:1e5", "clutter:2e5"}));
  EXPECT_EQ(loadSceneByName("temple").triangles.size(), makeTemple().triangles.size());
  EXPECT_EQ(loadSceneByName("cornell").name, "cornell");
  EXPECT_EQ(loadSceneByName("furnace").triangles.size(), makeFurnace().triangles.size());
  expectValidTriangle(loadSceneByName(kData + "valid_triangle.gltf"));
  try {
    loadSceneByName("sponza");
    ADD_FAILURE() << "unknown name accepted";
  } catch (const std::invalid_argument& e) {
    std::string message = e.what();
    for (const char* name : {"sponza", "temple", "cornell", "furnace", ".gltf", ".glb"})
      EXPECT_NE(message.find(name), std::string::npos) << message;
  }
  for (const char* missing : {"/nonexistent/scene.gltf", "/nonexistent/SCENE.GLB", "relative/missing.Gltf"}) {
    try {
      loadSceneByName(missing);
      ADD_FAILURE() << missing;
    } catch (const SceneLoadError& e) {
      EXPECT_EQ(std::string(e.what()), std::string(missing) + ": file not found");
    }
  }
  EXPECT_THROW(loadGltf(kData + "make_fixtures.py"), SceneLoadError);  // not a glTF extension
}

// The third-party scenes of ../shared/scenes (counts from its README).
class SharedScenes : public testing::Test {
 protected:
  void SetUp() override {
    if (!fs::is_directory(kShared)) GTEST_SKIP() << "no shared scenes at " << kShared;
  }
  static size_t emissiveMaterials(const Scene& s) {
    return static_cast<size_t>(std::count_if(s.materials.begin(), s.materials.end(),
                                             [](const Material& m) { return m.isEmissive(); }));
  }
};

TEST_F(SharedScenes, Box) {
  Scene s = loadGltf(kShared + "Box/Box.gltf");
  EXPECT_EQ(s.triangles.size(), 12u);
  EXPECT_EQ(s.name, "Box");
  EXPECT_NEAR(s.bounds().extent().x, 1.0f, 1e-5f);
  EXPECT_NEAR(s.bounds().extent().y, 1.0f, 1e-5f);
  ASSERT_EQ(s.viewpoints.size(), 1u);
  EXPECT_EQ(s.viewpoints[0].name, "default");
}

TEST_F(SharedScenes, CornellBox) {
  Scene s = loadGltf(kShared + "CornellBox/cornellBox.gltf");
  EXPECT_EQ(s.triangles.size(), 16732u);
  EXPECT_EQ(emissiveMaterials(s), 1u);
  // Its camera is called "default", the name of the computed view, so the node name is used.
  ASSERT_EQ(s.viewpoints.size(), 2u);
  EXPECT_EQ(s.viewpoints[0].name, "CamInst");
  EXPECT_EQ(s.viewpoints[1].name, "default");
}

TEST_F(SharedScenes, DamagedHelmet) {
  Scene s = loadGltf(kShared + "DamagedHelmet/DamagedHelmet.glb");
  EXPECT_EQ(s.triangles.size(), 15452u);
  ASSERT_EQ(s.materials.size(), 1u);
  ASSERT_GE(s.materials[0].baseColorTexture, 0);
  const Texture& t = s.textures[static_cast<size_t>(s.materials[0].baseColorTexture)];
  EXPECT_GT(t.width, 0u);
  EXPECT_EQ(t.rgba8.size(), static_cast<size_t>(t.width) * t.height);
  // Emission: factor 1 scaled by the mean of its (mostly dark) emissive texture.
  EXPECT_GT(s.materials[0].emissive.x, 0.0f);
  EXPECT_LT(s.materials[0].emissive.x, 0.5f);
}

TEST_F(SharedScenes, Sponza) {
  auto start = std::chrono::steady_clock::now();
  Scene s = loadGltf(kShared + "Sponza/Sponza.gltf");
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  RecordProperty("sponza_load_seconds", std::to_string(seconds));
  std::printf("Sponza: %zu triangles, %zu textures, loaded in %.2f s\n", s.triangles.size(),
              s.textures.size(), seconds);
  EXPECT_EQ(s.triangles.size(), 262087u);
  std::vector<std::string> names;
  for (const Viewpoint& v : s.viewpoints) names.push_back(v.name);
  EXPECT_EQ(names, (std::vector<std::string>{"CameraMain", "CameraAlternate", "CameraBalcony", "CameraAlcove",
                                             "default"}));
  // The .dds alternates are absent; the PNG sources still give the base colour textures.
  EXPECT_GE(s.textures.size(), 20u);
  for (const Texture& t : s.textures) EXPECT_EQ(t.rgba8.size(), static_cast<size_t>(t.width) * t.height);
  size_t textured = 0;
  for (const Material& m : s.materials) {
    textured += m.baseColorTexture >= 0;
    EXPECT_LT(m.baseColorTexture, static_cast<int>(s.textures.size()));
  }
  EXPECT_GE(textured, 20u);
  Bounds b = s.bounds();
  for (const Viewpoint& v : s.viewpoints)  // all cameras stand inside (or, default, outside) the atrium
    EXPECT_TRUE(v.name == "default" ||
                (glm::all(glm::greaterThan(v.position, b.min)) && glm::all(glm::lessThan(v.position, b.max))))
        << v.name;
}

}  // namespace
}  // namespace raylab
