// Settings as the window handles them: render flags laid over existing Settings (app/setting_flags.h) and
// the screenshot sidecar (app/sidecar.h). That a sidecar renders the same image again is tested on the GPU
// (tests/gpu/test_ui_sidecar.cpp).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>

#include <gtest/gtest.h>

#include "tests/temp_path.h"
#include "app/cli_options.h"
#include "app/setting_flags.h"
#include "app/sidecar.h"
#include "renderer/stats_json.h"

namespace raylab {
namespace {

// A Settings value with every field away from its default, as a user might leave it.
Settings unusualSettings() {
  Settings s;
  s.scene = "cornell";
  s.view = "front";
  s.width = 33, s.height = 17;
  s.bounces = 3, s.sppPerFrame = 2, s.frames = 4, s.seed = 9, s.exposure = 1.5f;
  s.strategy = KeyStrategy::Gaussian;
  s.sort = SortAlgorithm::Bitonic;
  s.grid.automatic = false;
  s.grid.cells = {8, 16, 32};
  s.clampToCamera = true, s.clampDistance = 12.5f;
  s.fixedFactor = 0.25f, s.emaAlpha = 0.5f, s.gaussOutlier = 2.0f, s.gaussReset = INFINITY;
  s.countSimt = true;
  return s;
}

// New render flags must be taught to the overlay, or `set KEY` and `--settings` silently ignore them.
TEST(UiSettings, EveryRenderFlagIsOverlaid) {
  std::vector<std::string> known = settingFlagNames();
  const std::string help = commonOptionsHelp();
  std::regex flag(R"((^|\n)\s+--([a-z-]+))");
  int seen = 0;
  for (std::sregex_iterator it(help.begin(), help.end(), flag), end; it != end; ++it, ++seen) {
    std::string name = (*it)[2];
    if (name == "device" || name == "validate" || name == "out" || name == "stats" || name == "settings") continue;
    EXPECT_NE(std::find(known.begin(), known.end(), name), known.end()) << "--" << name << " is not in setting_flags.cpp";
  }
  EXPECT_GT(seen, 15);
}

TEST(UiSettings, ApplyingAFlagChangesOnlyItsFields) {
  const Settings before = unusualSettings();
  Settings s = before;
  applySettingFlag(s, "strategy", "ema");
  Settings expected = before;
  expected.strategy = KeyStrategy::Ema;
  EXPECT_EQ(s, expected);
  applySettingFlag(s, "clamp", "off");
  EXPECT_FALSE(s.clampToCamera);
  EXPECT_EQ(s.clampDistance, before.clampDistance);
  applySettingFlag(s, "clamp", "3");
  EXPECT_TRUE(s.clampToCamera);
  EXPECT_EQ(s.clampDistance, 3.0f);
  applySettingFlag(s, "count-simt", "off");
  EXPECT_FALSE(s.countSimt);
  applySettingFlag(s, "size", "64x32");
  EXPECT_EQ(s.width, 64u);
  EXPECT_EQ(s.height, 32u);
  applySettingFlag(s, "heatmap", "cell-hit");
  EXPECT_EQ(s.heatmap, HeatmapView::CellHit);
  EXPECT_THROW(applySettingFlag(s, "bounces", "99"), UsageError);
  EXPECT_THROW(applySettingFlag(s, "count-simt", "maybe"), UsageError);
  EXPECT_THROW(applySettingFlag(s, "out", "x.png"), UsageError);
}

TEST(UiSettings, OverlayOnDefaultsEqualsTheCliParse) {
  std::vector<std::string> args = {"--scene", "cornell", "--size", "40x20", "--bounces", "6", "--strategy", "two-point",
                                    "--grid", "4x5x6", "--clamp", "7", "--gauss-reset", "inf", "--count-simt",
                                    "--out", "x.png", "--validate"};
  EXPECT_EQ(overlaySettingFlags(Settings{}, args), parseCommonOptions(args).settings);
  EXPECT_THROW(overlaySettingFlags(Settings{}, {"--bogus", "1"}), UsageError);
  EXPECT_NO_THROW(overlaySettingFlags(Settings{}, {"--script", "s.txt", "--reset"}, /*skipUnknown=*/true));
}

class UiSidecar : public ::testing::Test {
 protected:
  std::string path_ = test::testTempPath("raylab_test_sidecar_roundtrip", ".json");
  void TearDown() override { std::filesystem::remove(path_); }
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
  c.device.name = "test device";  // no Vulkan device here: the sidecar only records its description
  c.device.subgroupSize = 32;
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

}  // namespace
}  // namespace raylab
