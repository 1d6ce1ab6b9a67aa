// Settings::bvh wide on the device: the wide traversal (shaders/bvh_traverse_wide.glsl) renders the binary
// BVH's image up to ties. Both trees index the same BVH-order triangles and the same triangle test decides
// each hit, so a path differs only where the two trees find different hits: two triangles at the same t, or a
// hit on a binary box's face that an axis-parallel ray grazes (test_bvh_wide.cpp counts those on the CPU).
// Such a path then continues elsewhere, so its pixel differs a lot while the rest are bit for bit equal. The
// tolerance is stated that way: at most 1% of the pixels may differ at all, and the image mean by at most 0.5%.
// The steps (one wide node each) must differ from the binary ones, or the wide tree was never walked.
#include <cstring>
#include <string>

#include <gtest/gtest.h>

#include "tests/gpu_test.h"
#include "tests/render_helpers.h"
#include "scenes/procedural.h"

namespace raylab::test {
namespace {

class WideBvhRender : public GpuTest {};

struct Difference {
  size_t pixels = 0, differing = 0;
  double meanBinary = 0.0, meanWide = 0.0;
};

Difference difference(const std::vector<glm::vec3>& binary, const std::vector<glm::vec3>& wide) {
  Difference d;
  d.pixels = binary.size();
  for (size_t i = 0; i < binary.size() && i < wide.size(); ++i)
    if (std::memcmp(&binary[i], &wide[i], sizeof(glm::vec3)) != 0) ++d.differing;
  d.meanBinary = moments(binary).mean;
  d.meanWide = moments(wide).mean;
  return d;
}

void expectClose(const Difference& d, const std::string& what) {
  std::printf("%s: %zu of %zu pixels differ, mean %.6f binary, %.6f wide\n", what.c_str(), d.differing, d.pixels,
              d.meanBinary, d.meanWide);
  EXPECT_LE(d.differing, d.pixels / 100) << what;
  EXPECT_NEAR(d.meanWide, d.meanBinary, 0.005 * d.meanBinary) << what;
  EXPECT_GT(d.meanBinary, 0.0) << what;
}

// The temple's enclosed and open viewpoints, the wavefront (trace stage, shadow rays in shade) and the megakernel, fused
// trace+shade, over two frames of two samples.
TEST_F(WideBvhRender, RendersTheBinaryImageUpToTies) {
  Scene scene = makeTemple();
  for (const char* name : {"hall", "openings"}) {
    const Viewpoint& view = *scene.findViewpoint(name);
    Settings base = smallFrame(41, 23, 4);
    base.sppPerFrame = 2;
    base.frames = 2;
    for (Kernel kernel : {Kernel::Wavefront, Kernel::Megakernel})
      for (TraceShade traceShade : {TraceShade::Split, TraceShade::Fused}) {
        if (kernel == Kernel::Megakernel && traceShade == TraceShade::Fused) continue;  // nothing to fuse
        // Each collapse orders the triangles its way: both layouts then see that order.
        for (WideCollapse collapse : allValues<WideCollapse>()) {
          Settings binary = base;
          binary.bvh = BvhLayout::Binary;
          binary.kernel = kernel;
          binary.traceShade = traceShade;
          binary.wideCollapse = collapse;
          Settings wide = binary;
          wide.bvh = BvhLayout::Wide;
          expectClose(difference(renderRadiance(ctx(), scene, binary, view), renderRadiance(ctx(), scene, wide, view)),
                      view.name + " " + toString(kernel) + " " + toString(traceShade) + " " + toString(collapse));
        }
      }
  }
}

// The traversal statistics are defined for the wide tree too (a step being one wide node visited): the
// per-bounce mean steps and the virtual warp efficiency exist, and the camera rays take fewer wide steps than
// binary ones (a wide node does the work of up to 7 binary ones), which also shows the wide tree was walked.
TEST_F(WideBvhRender, CountsItsOwnSteps) {
  Scene scene = makeTemple();
  const Viewpoint& view = *scene.findViewpoint("hall");
  for (Kernel kernel : {Kernel::Wavefront, Kernel::Megakernel}) {
    Settings binary = smallFrame(41, 23, 3);
    binary.kernel = kernel;
    binary.bvh = BvhLayout::Binary;
    Settings wide = binary;
    wide.bvh = BvhLayout::Wide;
    PathTracer b(ctx(), scene, binary, view), w(ctx(), scene, wide, view);
    b.setDetailedStats(true);
    w.setDetailedStats(true);
    const FrameStats bs = b.renderFrame(), ws = w.renderFrame();
    const std::string what = toString(kernel);
    ASSERT_EQ(bs.bounces.size(), ws.bounces.size()) << what;
    ASSERT_FALSE(ws.bounces.empty()) << what;
    for (size_t i = 0; i < ws.bounces.size(); ++i) {
      EXPECT_GT(ws.bounces[i].meanTraversalSteps, 0.0) << what << " bounce " << i;
      EXPECT_GT(ws.bounces[i].virtualWarpEfficiency, 0.0) << what << " bounce " << i;
      EXPECT_LE(ws.bounces[i].virtualWarpEfficiency, 1.0) << what << " bounce " << i;
    }
    std::printf("hall camera rays, %s: mean steps binary %.2f, wide %.2f\n", what.c_str(),
                bs.bounces[0].meanTraversalSteps, ws.bounces[0].meanTraversalSteps);
    EXPECT_LT(ws.bounces[0].meanTraversalSteps, 0.7 * bs.bounces[0].meanTraversalSteps) << what;
  }
}

}  // namespace
}  // namespace raylab::test
