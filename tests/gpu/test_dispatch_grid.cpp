// Every path count on every device: dispatches made from a thread count run in rows of at most
// maxComputeWorkGroupCount[0] groups (renderer/vk/dispatch_size.h), indirect ones too (the sizes shaders
// write, dispatch_index.glsl). A context with rows of 3 groups makes a small frame run on many rows, so the
// row arithmetic of every stage is checked against the one-row image bit for bit; one frame of more than
// 4.2M paths (65536 groups of 64, one more than lavapipe's limit in x) checks the real case.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "scenes/procedural.h"
#include "tests/gpu_test.h"
#include "tests/render_helpers.h"

namespace raylab::test {

class DispatchGrid : public GpuTest {};

// While it lives, the shared context dispatches in rows of 3 work groups. (A second context for this
// crashed at exit on Debian 13's lavapipe and layer 1.4.309, after every test had passed.)
struct ShortRows {
  explicit ShortRows(VulkanContext& ctx) : ctx(ctx) { ctx.setDispatchRowGroups(3); }
  ~ShortRows() { ctx.setDispatchRowGroups(0); }
  VulkanContext& ctx;
};

// 37x19 at 2 spp is 1406 paths, 22 groups: 8 rows of 3 with a short last row, in every stage of the
// wavefront (direct and indirect, compacted or not, sorted, fused) and the megakernel.
TEST_F(DispatchGrid, ShortRowsRenderTheSameImage) {
  {
    ShortRows rows(ctx());
    ASSERT_EQ(ctx().info().dispatchRowGroups, 3u);
  }
  ASSERT_GT(ctx().info().dispatchRowGroups, 3u);
  Scene scene = makeTemple();
  const Viewpoint& view = *scene.findViewpoint("hall");
  Settings base = smallFrame(37, 19, 4);
  base.sppPerFrame = 2;
  base.frames = 2;
  struct Variant {
    std::string name;
    void (*change)(Settings&);
  };
  const std::vector<Variant> variants = {
      {"unsorted", [](Settings&) {}},
      {"no compaction", [](Settings& s) { s.compaction = Compaction::None; }},
      {"trace+shade fused", [](Settings& s) { s.traceShade = TraceShade::Fused; }},
      {"two-point radix", [](Settings& s) { s.strategy = KeyStrategy::TwoPoint; }},
      {"average bitonic, fusion both", [](Settings& s) {
         s.strategy = KeyStrategy::Average;
         s.sort = SortAlgorithm::Bitonic;
         s.fusion = Fusion::Both;
       }},
      {"oracle, fusion none", [](Settings& s) {
         s.strategy = KeyStrategy::Oracle;
         s.fusion = Fusion::None;
       }},
      {"megakernel", [](Settings& s) { s.kernel = Kernel::Megakernel; }},
  };
  for (const Variant& v : variants) {
    Settings s = base;
    v.change(s);
    std::vector<glm::vec3> rows;
    {
      ShortRows shortRows(ctx());
      rows = renderRadiance(ctx(), scene, s, view);
    }
    expectSameImage(rows, renderRadiance(ctx(), scene, s, view), v.name);
  }
}

// Heatmaps gather per path and colour per pixel: the same colours on short rows.
TEST_F(DispatchGrid, ShortRowsDrawTheSameHeatmaps) {
  Scene scene = makeTemple();
  const Viewpoint& view = *scene.findViewpoint("hall");
  for (HeatmapView heatmap : {HeatmapView::SortKey, HeatmapView::TraversalSteps, HeatmapView::CacheMean}) {
    Settings s = smallFrame(37, 19, 3);
    s.strategy = KeyStrategy::Average;
    s.heatmap = heatmap;
    PathTracer rows(ctx(), scene, s, view), row(ctx(), scene, s, view);
    {
      ShortRows shortRows(ctx());
      rows.renderFrame();
    }
    row.renderFrame();
    EXPECT_EQ(rows.readImage(), row.readImage()) << toString(heatmap);
  }
}

// 2048x2048 at 1 spp: 4,194,304 paths, 65536 groups of 64 (lavapipe launches at most 65535 in x, so this
// failed with "generate: 65536 work groups exceed the device limit"). One bounce of the Cornell box keeps it
// cheap; every camera ray must be traced (nothing lost in the second row) and the image must agree with a
// small render of the same view.
TEST_F(DispatchGrid, MoreThan4MPathsRender) {
  Scene scene = makeCornell();
  const Viewpoint& view = scene.viewpoints.front();
  Settings s = smallFrame(2048, 2048, 1);
  const auto start = std::chrono::steady_clock::now();
  PathTracer tracer(ctx(), scene, s, view);
  const FrameStats& stats = tracer.renderFrame();
  ASSERT_EQ(stats.bounces.size(), 1u);
  EXPECT_EQ(stats.bounces[0].rays, 2048u * 2048u) << "every camera ray is traced";
  std::vector<glm::vec3> image = tracer.readRadiance();
  std::printf("[ timing   ] 2048x2048, 1 bounce: %.1f s\n",
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  size_t finite = 0;
  for (const glm::vec3& p : image) finite += std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
  EXPECT_EQ(finite, image.size());
  const ImageMoments big = moments(image);
  const ImageMoments small = moments(renderRadiance(ctx(), scene, smallFrame(256, 256, 1), view));
  ASSERT_GT(small.mean, 0.0);
  EXPECT_NEAR(big.mean, small.mean, 5.0 * (big.standardError + small.standardError) + 0.01 * small.mean);
}

}  // namespace raylab::test
