// Every real glTF scene in ../shared/scenes and every built-in scene loads and renders a non-black image
// on the test device (from the framing `default` view where the loader made one, else the first), and
// stays finite from every viewpoint. Interior cameras such as Sponza's alcove, lit only through the roof
// opening, may legitimately be near black at a few samples, so they are checked for finiteness only.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "tests/gpu_test.h"
#include "tests/render_helpers.h"
#include "scenes/scene_library.h"

namespace raylab::test {

class SceneRenders : public GpuTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(SceneRenders, NonBlackAndFinite) {
  std::string name = GetParam();
  if (name.find('/') != std::string::npos && !std::filesystem::exists(name)) GTEST_SKIP() << name << " is absent";
  Scene scene = loadSceneByName(name);
  Settings s;
  s.width = 24;
  s.height = 16;
  s.bounces = 3;
  s.frames = 2;
  for (const Viewpoint& view : scene.viewpoints) {
    std::vector<glm::vec3> img = renderRadiance(ctx(), scene, s, view);
    ImageMoments m = moments(img);
    bool framing = scene.findViewpoint("default") ? view.name == "default" : &view == &scene.viewpoints.front();
    if (framing) {
      EXPECT_GT(m.mean, 1e-3) << name << " from " << view.name << " renders black";
    }
    EXPECT_TRUE(std::isfinite(m.mean)) << name << " from " << view.name;
  }
}

INSTANTIATE_TEST_SUITE_P(All, SceneRenders,
                         ::testing::Values("temple", "cornell", "furnace", "temple-detail:1e4", "clutter:5e4",
                                           RAYLAB_SOURCE_DIR "/../shared/scenes/Box/Box.gltf",
                                           RAYLAB_SOURCE_DIR "/../shared/scenes/CornellBox/cornellBox.gltf",
                                           RAYLAB_SOURCE_DIR "/../shared/scenes/DamagedHelmet/DamagedHelmet.glb",
                                           RAYLAB_SOURCE_DIR "/../shared/scenes/Sponza/Sponza.gltf"));

}  // namespace raylab::test

namespace raylab::test {

// The first image anyone sees (`raylab` without a display, the window's first frames): the default scene
// from its default viewpoint must show the scene within a few samples, bright and with structure, not
// the near-black noise of an indirectly lit interior.
class FirstImage : public GpuTest {};

TEST_F(FirstImage, DefaultViewIsBrightAndInformative) {
  Scene scene = loadSceneByName(Settings{}.scene);
  Settings s;
  s.width = 64, s.height = 32;
  PathTracer tracer(ctx(), scene, s, scene.viewpoints.front());
  for (int f = 0; f < 4; ++f) tracer.renderFrame();
  std::vector<uint32_t> rgba = tracer.readImage();
  double sum = 0.0, sum2 = 0.0;
  for (uint32_t p : rgba) {
    double luma = ((p & 255) + ((p >> 8) & 255) + ((p >> 16) & 255)) / (3.0 * 255.0);
    sum += luma, sum2 += luma * luma;
  }
  double mean = sum / rgba.size(), sd = std::sqrt(std::max(0.0, sum2 / rgba.size() - mean * mean));
  RecordProperty("mean", std::to_string(mean));
  EXPECT_GT(mean, 0.5) << "the default view at 4 spp is dark (mean display value " << mean << ")";
  EXPECT_GT(sd, 0.05) << "the default view shows no structure";
}

}  // namespace raylab::test
