// No combination of settings crashes: every strategy x heatmap x sort x kernel either shows its view (with
// data in it) or is unavailable with a reason, and then renders the image instead. One tracer walks the
// whole product through applySettings, as the window does, so switches such as gaussian -> fixed with a
// cache view showing (which once read a cache that no longer existed) are covered too.
#include <algorithm>
#include <array>

#include <gtest/gtest.h>

#include "tests/gpu_test.h"
#include "renderer/heatmap/heatmap_rules.h"
#include "renderer/reorder/key_functions.h"
#include "renderer/path_tracer.h"
#include "scenes/procedural.h"

namespace raylab::test {
namespace {

constexpr uint32_t kEmptyPixel = 0xFF1F1F1Fu;  // heatmap_colorize.comp's colour for "no path at this bounce"

Settings tinySettings() {
  Settings s;
  s.width = 32;
  s.height = 16;
  s.bounces = 2;
  return s;
}

}  // namespace

TEST(HeatmapRules, SayWhyAViewHasNoData) {
  Settings s = tinySettings();
  s.strategy = KeyStrategy::Fixed;
  s.heatmap = HeatmapView::CacheMean;
  ASSERT_TRUE(heatmapUnavailable(s));
  EXPECT_NE(heatmapUnavailable(s)->find("no length cache"), std::string::npos) << *heatmapUnavailable(s);
  EXPECT_EQ(heatmapShown(s), HeatmapView::None);
  s.strategy = KeyStrategy::Gaussian;
  EXPECT_FALSE(heatmapUnavailable(s));
  EXPECT_EQ(heatmapShown(s), HeatmapView::CacheMean);
  s.kernel = Kernel::Megakernel;
  EXPECT_NE(heatmapUnavailable(s).value_or("").find("wavefront"), std::string::npos);
  s.kernel = Kernel::Wavefront;
  s.sort = SortAlgorithm::None;
  EXPECT_NE(heatmapUnavailable(s).value_or("").find("needs a sort"), std::string::npos);
  s.sort = SortAlgorithm::Radix;
  s.strategy = KeyStrategy::Origin;
  s.heatmap = HeatmapView::CellHit;
  EXPECT_NE(heatmapUnavailable(s).value_or("").find("estimates no ray length"), std::string::npos);
  // Camera rays get no keys; one bounce shows bounce 0 whatever was asked for, and keeps the request.
  s.strategy = KeyStrategy::Fixed;
  s.bounces = 1;
  s.heatmapBounce = 3;
  EXPECT_EQ(heatmapBounceShown(s), 0u);
  EXPECT_NE(heatmapUnavailable(s).value_or("").find("bounce 0"), std::string::npos);
  s.bounces = 8;
  EXPECT_EQ(heatmapBounceShown(s), 3u);
  EXPECT_FALSE(heatmapUnavailable(s));
  // The trace's own views need nothing.
  for (Kernel k : {Kernel::Wavefront, Kernel::Megakernel})
    for (HeatmapView v : {HeatmapView::None, HeatmapView::TraversalSteps, HeatmapView::WarpEfficiency}) {
      s.kernel = k;
      EXPECT_FALSE(heatmapUnavailable(s, v)) << toString(v);
    }
}

class HeatmapProduct : public GpuTest {};

TEST_F(HeatmapProduct, EveryCombinationRendersOrSaysWhyNot) {
  Scene scene = makeTemple();
  const Viewpoint& view = *scene.findViewpoint("hall");
  PathTracer tracer(ctx(), scene, tinySettings(), view);
  int shown = 0, refused = 0;
  // Relative to the count before: the context is shared by every test of one process, and a validation-check
  // test before this one may have provoked errors on purpose.
  const uint32_t errorsBefore = ctx().validationErrors();
  for (Kernel kernel : {Kernel::Wavefront, Kernel::Megakernel})
    for (SortAlgorithm sort : {SortAlgorithm::None, SortAlgorithm::Bitonic, SortAlgorithm::Radix})
      for (KeyStrategy strategy : allKeyStrategies())
        for (HeatmapView heatmap : allHeatmapViews()) {
          Settings s = tinySettings();
          s.kernel = kernel, s.sort = sort, s.strategy = strategy, s.heatmap = heatmap;
          // The colouring options rotate through the product: every key colour, scale and range lock meets
          // every view many times without multiplying the renders.
          const int n = shown + refused;
          s.heatmapKeyColour = std::array{HeatmapKeyColour::Cell, HeatmapKeyColour::Rank, HeatmapKeyColour::Hash}[n % 3];
          s.heatmapScale = n % 2 ? HeatmapScale::Log : HeatmapScale::Linear;
          s.heatmapRange = {n % 5 == 0, 1.0f, 50.0f};
          std::string what = toString(kernel) + "/" + toString(sort) + "/" + toString(strategy) + "/" + toString(heatmap) +
                             "/" + toString(s.heatmapKeyColour) + "/" + toString(s.heatmapScale);
          std::optional<std::string> why = heatmapUnavailable(s);
          tracer.applySettings(s);
          tracer.renderFrame();
          ASSERT_EQ(ctx().validationErrors(), errorsBefore) << what;
          if (why) {
            EXPECT_FALSE(why->empty()) << what;
            ++refused;
            continue;
          }
          ++shown;
          if (heatmap == HeatmapView::None) continue;
          std::vector<uint32_t> image = tracer.readImage();
          EXPECT_TRUE(std::any_of(image.begin(), image.end(), [](uint32_t p) { return p != kEmptyPixel; }))
              << what << ": an available view showed no data";
          EXPECT_FALSE(tracer.stats().heatmap.unit.empty()) << what;
        }
  // 2 kernels x 3 sorts x 11 strategies x 3 trace views, plus the key views of the 10 strategies x 2 sorts
  // (sort-key 20, cell-hit 6 x 2, cache 3 x 2 x 2).
  EXPECT_EQ(shown, 198 + 20 + 12 + 12);
  EXPECT_EQ(refused, 2 * 3 * 11 * 7 - shown);
}

// The window's reported crash, step by step: a cache view showing, then a strategy without a cache.
TEST_F(HeatmapProduct, CacheViewSurvivesLosingTheCache) {
  Scene scene = makeTemple();
  Settings s = tinySettings();
  s.strategy = KeyStrategy::Gaussian;
  PathTracer tracer(ctx(), scene, s, *scene.findViewpoint("alley"));
  tracer.renderFrame();
  s.heatmap = HeatmapView::CacheMean;
  tracer.applySettings(s);
  tracer.renderFrame();
  EXPECT_EQ(tracer.stats().heatmap.unit, "cached length mean");
  s.strategy = KeyStrategy::Fixed;
  tracer.applySettings(s);
  tracer.renderFrame();
  EXPECT_TRUE(tracer.stats().heatmap.view.empty()) << "an unavailable view must not be gathered";
}

}  // namespace raylab::test
