// A window screenshot's sidecar re-renders what the window showed (issue 38): for every heatmap, chosen where
// the window offers it, then every order of two strategy switches the strategy combo allows, the sidecar's
// settings are accepted by `raylab render --settings` (no heatmap it would refuse) and ask for the view the
// window showed. And the sidecar says whether the length cache learned over the image's frames only
// (app/learned_history.h).
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "tests/temp_path.h"
#include "app/learned_history.h"
#include "app/sidecar.h"
#include "renderer/heatmap/heatmap_rules.h"
#include "renderer/settings/settings_validation.h"

namespace raylab {
namespace {

class SidecarHeatmaps : public ::testing::Test {
 protected:
  std::string path_ = test::testTempPath("raylab_test_sidecar", ".json");
  void TearDown() override { std::filesystem::remove(path_); }
};

// The window's strategy combo (ui/method_panel.cpp comboSetting) offers a value only where the settings
// stay valid.
bool comboAllows(const Settings& s, KeyStrategy next) {
  Settings candidate = s;
  candidate.strategy = next;
  return !settingsError(candidate).has_value();
}

TEST_F(SidecarHeatmaps, EveryViewUnderEveryStrategySwitchOrderReRenders) {
  int checked = 0, notShown = 0;
  for (HeatmapView view : allHeatmapViews()) {
    for (KeyStrategy first : allKeyStrategies()) {
      Settings start;
      start.bounces = 3, start.heatmapBounce = 1;
      start.strategy = first;
      if (settingsError(start) || heatmapUnavailable(start, view)) continue;  // the heatmap combo greys it out
      start.heatmap = view;
      for (KeyStrategy second : allKeyStrategies()) {
        if (!comboAllows(start, second)) continue;
        Settings middle = start;
        middle.strategy = second;
        for (KeyStrategy third : allKeyStrategies()) {
          if (!comboAllows(middle, third)) continue;
          Settings shown = middle;
          shown.strategy = third;
          SidecarContent c;
          c.kind = "render";
          c.settings = shown;
          const nlohmann::json j = makeSidecar(c);
          std::ofstream(path_) << j.dump(2);
          std::optional<Viewpoint> camera;
          const CommonOptions back = parseOptionsWithSettingsFile({"--settings", path_}, &camera);
          // What `raylab render` checks before it renders (app/render_command.cpp).
          ASSERT_FALSE(heatmapUnavailable(back.settings))
              << toString(view) << ": " << toString(first) << " -> " << toString(second) << " -> " << toString(third);
          EXPECT_EQ(back.settings.heatmap, heatmapShown(shown)) << toString(view) << " under " << toString(third);
          const bool hidden = heatmapShown(shown) != view;
          EXPECT_EQ(j.contains("heatmap_not_shown"), hidden);
          if (hidden) {
            EXPECT_EQ(j["heatmap_not_shown"]["asked"], toString(view));
            ++notShown;
          }
          ++checked;
        }
      }
    }
  }
  EXPECT_GT(checked, 500);
  EXPECT_GT(notShown, 50);  // the case (cache-mean, then fixed) is among them
}

TEST(LearnedHistory, ReproducibleOnlyWhenTheCacheStartedWithTheAccumulation) {
  int tracer = 0, other = 0;
  LearnedHistory h;
  // A new tracer: cache and accumulation start together.
  for (uint32_t f = 1; f <= 4; ++f) h.onFrame(&tracer, f, 1);
  EXPECT_TRUE(h.state(true, 4, 1).reproducible);
  EXPECT_TRUE(h.state(false, 4, 1).note.empty());  // no cache: nothing to say
  // The camera moved (accumulation restarts, the cache keeps learning): a re-render learns less.
  for (uint32_t f = 1; f <= 3; ++f) h.onFrame(&tracer, f, 1);
  EXPECT_FALSE(h.state(true, 3, 1).reproducible);
  EXPECT_FALSE(h.state(false, 3, 1).reproducible == false);  // a strategy that learns nothing reproduces
  // Restart learning (L): both start again.
  h.onFrame(&tracer, 1, 2);
  h.onFrame(&tracer, 2, 2);
  EXPECT_TRUE(h.state(true, 2, 2).reproducible);
  // A grid change mid-accumulation makes a new cache (the image keeps accumulating).
  h.onFrame(&tracer, 3, 3);
  EXPECT_FALSE(h.state(true, 3, 3).reproducible);
  EXPECT_NE(h.state(true, 3, 3).note.find("press L"), std::string::npos);
  // A new scene is a new tracer, met at its first frame.
  h.onFrame(&other, 1, 1);
  EXPECT_TRUE(h.state(true, 1, 1).reproducible);
}

TEST_F(SidecarHeatmaps, LearnedStateIsRecordedAndReadBack) {
  SidecarContent c;
  c.kind = "render";
  c.settings.strategy = KeyStrategy::Gaussian;
  c.settings.heatmap = HeatmapView::SortKey;
  c.settings.bounces = 3, c.settings.heatmapBounce = 1;
  c.learned = {false, "learned before"};
  std::ofstream(path_) << makeSidecar(c).dump(2);
  std::string note;
  std::optional<Viewpoint> camera;
  parseOptionsWithSettingsFile({"--settings", path_}, &camera, nullptr, &note);
  EXPECT_EQ(note, "learned before");
  c.learned = {true, "learned over this image's frames only"};
  std::ofstream(path_) << makeSidecar(c).dump(2);
  parseOptionsWithSettingsFile({"--settings", path_}, &camera, nullptr, &note);
  EXPECT_EQ(note, "");
}

}  // namespace
}  // namespace raylab
