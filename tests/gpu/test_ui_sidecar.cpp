// Screenshot sidecars (app/sidecar.h): settings and camera survive the round trip through the JSON, and
// `render --settings SIDECAR.json` reproduces the image it describes.
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "app/cli_options.h"
#include "app/sidecar.h"
#include "renderer/path_tracer.h"
#include "renderer/stats_json.h"
#include "scenes/scene_library.h"
#include "tests/gpu_test.h"
#include "tests/settings_support.h"

namespace raylab {
namespace {

using test::unusualSettings;

class UiSidecar : public test::GpuTest {
 protected:
  std::string path_ = (std::filesystem::temp_directory_path() / "raylab_test_sidecar.json").string();
  void TearDown() override {
    std::filesystem::remove(path_);
    GpuTest::TearDown();
  }
  void write(const SidecarContent& c) { std::ofstream(path_) << makeSidecar(c).dump(2); }
};

TEST_F(UiSidecar, SettingsAndCameraRoundTrip) {
  SidecarContent c;
  c.kind = "render";
  c.settings = unusualSettings();
  c.camera.name = "moved";
  c.camera.position = {0.1f, 2.5f, -3.25f};
  c.camera.target = {1.0f / 3.0f, 0.0f, 7.0f};
  c.camera.yfovRadians = 0.7f;
  c.device = ctx().info();
  write(c);
  Sidecar back = readSidecar(path_);
  EXPECT_EQ(toJson(back.settings), toJson(c.settings));
  ASSERT_TRUE(back.camera);
  EXPECT_EQ(back.camera->position, c.camera.position);
  EXPECT_EQ(back.camera->target, c.camera.target);
  EXPECT_FLOAT_EQ(back.camera->yfovRadians, c.camera.yfovRadians);

  // Flags after --settings change only what they name; --view replaces the saved camera.
  std::optional<Viewpoint> camera;
  CommonOptions o = parseOptionsWithSettingsFile({"--settings", path_, "--bounces", "7"}, &camera);
  Settings expected = back.settings;
  expected.bounces = 7;
  EXPECT_EQ(toJson(o.settings), toJson(expected));
  EXPECT_TRUE(camera);
  camera.reset();
  parseOptionsWithSettingsFile({"--view", "front", "--settings", path_}, &camera);
  EXPECT_FALSE(camera);
  EXPECT_THROW(readSidecar(path_ + ".missing"), UsageError);
}

// A screenshot's sidecar, loaded back, renders the very same image: settings (frames included) and
// camera are all it takes.
TEST_F(UiSidecar, ReproducesTheImage) {
  Scene scene = loadSceneByName("cornell");
  Settings s;
  s.scene = "cornell";
  s.width = 24, s.height = 16, s.bounces = 3, s.seed = 5, s.frames = 3;
  s.strategy = KeyStrategy::Gaussian;  // with a length cache: its state is not in the sidecar, nor needed
  s.sort = SortAlgorithm::Radix;
  Viewpoint moved = scene.viewpoints.front();
  moved.position += glm::vec3(0.013f, -0.021f, 0.037f);  // a camera no named viewpoint has

  SidecarContent c;
  {
    PathTracer tracer(ctx(), scene, s, moved);
    for (uint32_t f = 0; f < s.frames; ++f) tracer.renderFrame();
    c.settings = tracer.settings();
    c.settings.frames = tracer.accumulatedFrames();
    c.camera = tracer.camera();
    c.stats = tracer.stats();
    c.imageWidth = s.width, c.imageHeight = s.height;
    c.device = ctx().info();
    write(c);
    std::vector<uint32_t> original = tracer.readImage();

    // What `raylab render --settings FILE` does (see app/sidecar.h).
    std::optional<Viewpoint> camera;
    CommonOptions options = parseOptionsWithSettingsFile({"--settings", path_}, &camera);
    ASSERT_TRUE(camera);
    PathTracer again(ctx(), scene, options.settings, *camera);
    for (uint32_t f = 0; f < options.settings.frames; ++f) again.renderFrame();
    EXPECT_EQ(again.readImage(), original);
  }
}

}  // namespace
}  // namespace raylab
