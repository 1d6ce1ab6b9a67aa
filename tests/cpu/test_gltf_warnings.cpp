// tinygltf's load warnings as the loader prints them (scenes/gltf_warnings.h): absent image files no
// material uses are summarised as unused, those a material uses are named, other warnings are kept.
#include <gtest/gtest.h>

#include <tiny_gltf.h>

#include "scenes/gltf_warnings.h"

namespace raylab::gltf {
namespace {

// Sponza's shape: material 0 reads image 0 (a .png) as base colour; images 1 and 2 (.dds) are only an
// extension's alternative, and image 3 is an emissive texture of a material that does not emit.
tinygltf::Model sponzaLike() {
  tinygltf::Model m;
  for (const char* uri : {"textures/wall.png", "vase_plant.dds", "wall.dds", "glow.png"}) {
    tinygltf::Image image;
    image.uri = uri;
    m.images.push_back(image);
  }
  for (int source : {0, -1, 3}) {
    tinygltf::Texture t;
    t.source = source;
    m.textures.push_back(t);
  }
  tinygltf::Material wall;
  wall.pbrMetallicRoughness.baseColorTexture.index = 0;
  wall.emissiveTexture.index = 2;
  wall.emissiveFactor = {0.0, 0.0, 0.0};
  m.materials.push_back(wall);
  return m;
}

TEST(GltfWarnings, ImagesUsedAreBaseColourAndEmittingEmissive) {
  tinygltf::Model m = sponzaLike();
  EXPECT_EQ(imagesUsedByMaterials(m), (std::set<int>{0}));
  m.materials[0].emissiveFactor = {1.0, 0.5, 0.0};
  EXPECT_EQ(imagesUsedByMaterials(m), (std::set<int>{0, 3}));
}

TEST(GltfWarnings, AbsentFilesAreToldApartByUse) {
  const std::string warnings =
      "File not found : /data/sponza/vase_plant.dds\n"
      "File not found : /data/sponza/wall.dds\n"
      "File not found : /data/sponza/textures/wall.png\n"
      "Failed to load external 'uri' for image[1] name = [vase_plant]\n"
      "Failed to load external 'uri' for image[0] name = [wall]\n"
      "Unknown extension MSFT_texture_dds\n";
  std::vector<std::string> lines = summariseLoadWarnings(warnings, sponzaLike());
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[0], "1 file(s) not found that the scene uses (drawn untextured): wall.png");
  EXPECT_EQ(lines[1], "2 image file(s) not found that no material the lab reads uses (nothing lost): "
                      "vase_plant.dds, wall.dds");
  EXPECT_EQ(lines[2], "Failed to load external 'uri' for image[0] name = [wall]");  // a used image's: kept
  EXPECT_EQ(lines[3], "Unknown extension MSFT_texture_dds");
}

TEST(GltfWarnings, ManyLinesAreCounted) {
  std::string warnings;
  for (int i = 0; i < 7; ++i) warnings += "File not found : t" + std::to_string(i) + ".dds\n";
  for (int i = 0; i < 5; ++i) warnings += "odd " + std::to_string(i) + "\n";
  tinygltf::Model m;
  for (int i = 0; i < 7; ++i) {
    tinygltf::Image image;
    image.uri = "t" + std::to_string(i) + ".dds";
    m.images.push_back(image);
  }
  std::vector<std::string> lines = summariseLoadWarnings(warnings, m);
  ASSERT_EQ(lines.size(), 5u);
  EXPECT_EQ(lines[0], "7 image file(s) not found that no material the lab reads uses (nothing lost): "
                      "t0.dds, t1.dds, t2.dds and 4 more");
  EXPECT_EQ(lines[4], "... and 2 more warnings from tinygltf");
}

}  // namespace
}  // namespace raylab::gltf
