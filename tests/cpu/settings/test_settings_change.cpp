// SettingsChange: the one diff between two Settings that decides what the renderer reallocates, restarts,
// resets and uploads. Each field is changed alone and must ask for exactly what it needs.
#include <algorithm>
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "renderer/settings/settings.h"

namespace raylab {
namespace {

struct Case {
  std::string field;
  std::function<void(Settings&)> change;
  SettingsChange want;
};

SettingsChange wants(bool reallocate, bool accumulation, bool cache, bool keyParameters) {
  SettingsChange c;
  c.reallocate = reallocate;
  c.resetAccumulation = accumulation;
  c.resetCache = cache;
  c.keyParameters = keyParameters;
  return c;
}

const std::vector<Case>& cases() {
  //                                    reallocate, accumulation, cache, key parameters
  static const std::vector<Case> all = {
      {"scene", [](Settings& s) { s.scene = "cornell"; }, wants(false, true, true, true)},
      {"view", [](Settings& s) { s.view = "hall"; }, wants(false, true, false, false)},
      {"width", [](Settings& s) { s.width = 640; }, wants(true, true, false, true)},
      {"height", [](Settings& s) { s.height = 100; }, wants(true, true, false, true)},
      {"sppPerFrame", [](Settings& s) { s.sppPerFrame = 3; }, wants(true, true, false, true)},
      // Path state does not depend on the bounce count: no reallocation, only a new image.
      {"bounces", [](Settings& s) { s.bounces = 7; }, wants(false, true, false, false)},
      {"seed", [](Settings& s) { s.seed = 42; }, wants(false, true, false, false)},
      {"frames", [](Settings& s) { s.frames = 9; }, wants(false, false, false, false)},
      {"exposure", [](Settings& s) { s.exposure = 2.0f; }, wants(false, false, false, false)},
      // The megakernel estimates the same integral; switching keeps accumulating, as the window does.
      {"kernel", [](Settings& s) { s.kernel = Kernel::Megakernel; }, wants(false, false, false, false)},
      // So do the driver's traversal and SER: the same rays, other stage costs.
      {"tracer", [](Settings& s) { s.tracer = Tracer::Rt; }, wants(false, false, false, false)},
      {"ser", [](Settings& s) { s.ser = Ser::Hint; }, wants(false, false, false, false)},
      // Another BVH layout may break ties between equally near triangles otherwise: a new image.
      {"bvh", [](Settings& s) { s.bvh = s.bvh == BvhLayout::Wide ? BvhLayout::Binary : BvhLayout::Wide; },
       wants(false, true, false, false)},
      // Sorting never changes the image (the central invariant): strategy, sort and grid keep it.
      {"strategy", [](Settings& s) { s.strategy = KeyStrategy::Ema; }, wants(false, false, true, true)},
      {"sort", [](Settings& s) { s.sort = SortAlgorithm::Bitonic; }, wants(false, false, false, false)},
      {"sortPolicy", [](Settings& s) { s.sortPolicy = SortPolicy::Auto; }, wants(false, false, false, false)},
      {"sortBits", [](Settings& s) { s.sortBits = 8; }, wants(false, false, false, false)},
      {"learnEvery", [](Settings& s) { s.learnEvery = 4; }, wants(false, false, false, false)},
      {"fusion", [](Settings& s) { s.fusion = Fusion::Both; }, wants(false, false, false, false)},
      {"compaction", [](Settings& s) { s.compaction = Compaction::None; }, wants(false, false, false, false)},
      {"traceShade", [](Settings& s) { s.traceShade = TraceShade::Fused; }, wants(false, false, false, false)},
      {"grid", [](Settings& s) { s.grid.autoCells = 32; }, wants(false, false, true, true)},
      {"clampToCamera", [](Settings& s) { s.clampToCamera = true; }, wants(false, false, true, true)},
      {"clampDistance", [](Settings& s) { s.clampDistance = 5.0f; }, wants(false, false, true, true)},
      {"fixedFactor", [](Settings& s) { s.fixedFactor = 0.25f; }, wants(false, false, true, true)},
      // Thresholds: new parameters on the GPU, but what the cache learned stays.
      {"emaAlpha", [](Settings& s) { s.emaAlpha = 0.5f; }, wants(false, false, false, true)},
      {"gaussOutlier", [](Settings& s) { s.gaussOutlier = 2.0f; }, wants(false, false, false, true)},
      {"gaussReset", [](Settings& s) { s.gaussReset = 5.0f; }, wants(false, false, false, true)},
      {"countSimt", [](Settings& s) { s.countSimt = true; }, wants(false, false, false, false)},
      {"heatmap", [](Settings& s) { s.heatmap = HeatmapView::TraversalSteps; }, wants(false, false, false, false)},
      {"heatmapBounce", [](Settings& s) { s.heatmapBounce = 2; }, wants(false, false, false, false)},
      // Heatmap colouring is display only.
      {"heatmapKeyColour", [](Settings& s) { s.heatmapKeyColour = HeatmapKeyColour::Rank; }, wants(false, false, false, false)},
      {"heatmapScale", [](Settings& s) { s.heatmapScale = HeatmapScale::Log; }, wants(false, false, false, false)},
      {"heatmapRange", [](Settings& s) { s.heatmapRange = {true, 2.0f, 40.0f}; }, wants(false, false, false, false)},
  };
  return all;
}

void expectChange(const SettingsChange& got, const SettingsChange& want, const std::string& what) {
  EXPECT_EQ(got.reallocate, want.reallocate) << what << ": reallocate";
  EXPECT_EQ(got.resetAccumulation, want.resetAccumulation) << what << ": resetAccumulation";
  EXPECT_EQ(got.resetCache, want.resetCache) << what << ": resetCache";
  EXPECT_EQ(got.keyParameters, want.keyParameters) << what << ": keyParameters";
}

TEST(SettingsChange, EachFieldAsksForWhatItNeeds) {
  const Settings base;
  for (const Case& c : cases()) {
    Settings next = base;
    c.change(next);
    ASSERT_FALSE(next == base) << c.field << " did not change anything";
    EXPECT_EQ(next.requiresAccumulationReset(base), c.want.resetAccumulation) << c.field;
    EXPECT_EQ(next.requiresCacheReset(base), c.want.resetCache) << c.field;
    expectChange(SettingsChange::between(base, next), c.want, c.field);
    // The diff is symmetric: changing back asks for the same.
    expectChange(SettingsChange::between(next, base), c.want, c.field + " (back)");
  }
}

// The auto sort policy's cost history holds for one view, image, key, sort, policy, kernel and tracer only; settings
// that change none of those (exposure, heatmap, frame count) keep it.
TEST(SettingsChange, SortCostsResetWhenWhatTheyMeasuredChanges) {
  const Settings base;
  const std::vector<std::string> keep = {"frames",        "exposure",         "countSimt",   "heatmap",
                                          "heatmapBounce", "heatmapKeyColour", "heatmapScale", "heatmapRange"};
  for (const Case& c : cases()) {
    Settings next = base;
    c.change(next);
    const bool kept = std::find(keep.begin(), keep.end(), c.field) != keep.end();
    EXPECT_EQ(SettingsChange::between(base, next).resetSortCosts, !kept) << c.field;
  }
  EXPECT_FALSE(SettingsChange::cameraMove(base).resetSortCosts);
}

TEST(SettingsChange, NoChangeAsksForNothing) {
  Settings s;
  s.strategy = KeyStrategy::Gaussian;
  EXPECT_EQ(SettingsChange::between(s, s), SettingsChange{});
  EXPECT_FALSE(s.requiresAccumulationReset(s));
  EXPECT_FALSE(s.requiresCacheReset(s));
}

TEST(SettingsChange, FieldsCombine) {
  Settings base, next;
  next.width = 100;                   // reallocate, restart
  next.strategy = KeyStrategy::Fixed;  // new cache
  next.exposure = 3.0f;               // nothing
  expectChange(SettingsChange::between(base, next), wants(true, true, true, true), "width + strategy + exposure");
}

// A camera move restarts the image; the key grid (and its uploaded parameters) follows the camera only
// when it is clamped to it, so flying with an unclamped grid uploads nothing.
TEST(SettingsChange, CameraMoveUploadsKeysOnlyForAClampedGrid) {
  Settings s;
  s.strategy = KeyStrategy::TwoPoint;
  expectChange(SettingsChange::cameraMove(s), wants(false, true, false, false), "unclamped camera move");
  s.clampToCamera = true;
  expectChange(SettingsChange::cameraMove(s), wants(false, true, false, true), "clamped camera move");
}

}  // namespace
}  // namespace raylab
