// A screenshot's sidecar (app/sidecar.h), loaded back, renders the very same image. The sidecar's round
// trip and the flags laid over it are tested on the CPU (tests/cpu/test_ui_settings.cpp).
#include <filesystem>
#include <fstream>
#include <optional>

#include <gtest/gtest.h>

#include "tests/temp_path.h"
#include "app/cli_options.h"
#include "app/sidecar.h"
#include "renderer/path_tracer.h"
#include "scenes/scene_library.h"
#include "tests/gpu_test.h"

namespace raylab {
namespace {

class UiSidecar : public test::GpuTest {
 protected:
  std::string path_ = test::testTempPath("raylab_test_sidecar_render", ".json");
  void TearDown() override {
    std::filesystem::remove(path_);
    GpuTest::TearDown();
  }
  void write(const SidecarContent& c) { std::ofstream(path_) << makeSidecar(c).dump(2); }
};

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
