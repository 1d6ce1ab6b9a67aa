// Settings as the window handles them: render flags laid over existing Settings (app/setting_flags.h).
// The screenshot sidecar's round trip is in tests/gpu/test_ui_sidecar.cpp.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>

#include <gtest/gtest.h>

#include "app/cli_options.h"
#include "app/setting_flags.h"
#include "renderer/stats_json.h"
#include "tests/settings_support.h"

namespace raylab {
namespace {

using test::unusualSettings;

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

}  // namespace
}  // namespace raylab
