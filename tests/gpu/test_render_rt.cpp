// The rt tracer (VK_KHR_ray_tracing_pipeline) against the compute tracer: the same estimator through the
// driver's traversal must agree statistically with ours, and within the rt tracer sorting must still
// never change the image. Devices without the extensions (Debian 12's lavapipe) skip with the reason.
#include <cstring>

#include <gtest/gtest.h>

#include "renderer/rt_tracer.h"
#include "scenes/procedural.h"
#include "tests/gpu_test.h"
#include "tests/render_helpers.h"

namespace raylab::test {

class RtTracerTest : public GpuTest {
 protected:
  void SetUp() override {
    GpuTest::SetUp();
    Settings rt;
    rt.tracer = Tracer::Rt;
    if (std::string why = unsupportedSettings(ctx().info(), rt); !why.empty()) GTEST_SKIP() << why;
  }
  static Settings small(const char* scene, Tracer tracer) {
    Settings s;
    s.scene = scene;
    s.width = 40;
    s.height = 24;
    s.bounces = 4;
    s.frames = 6;
    s.sppPerFrame = 2;
    s.tracer = tracer;
    return s;
  }
};

// As RenderConsistency.MegakernelAgreesWithWavefront: relative MSE between the tracers within 1.5x the
// relative MSE between two seeds of one tracer, image means within four standard errors.
void expectAgreement(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b, double noise,
                     const char* what) {
  double gap = relativeMse(a, b);
  EXPECT_LE(gap, 1.5 * noise) << what << ": gap " << gap << " vs seed noise " << noise;
  ImageMoments ma = moments(a), mb = moments(b);
  EXPECT_NEAR(ma.mean, mb.mean, 4.0 * std::hypot(ma.standardError, mb.standardError)) << what;
}

TEST_F(RtTracerTest, RtWavefrontAndMegakernelAgreeWithCompute) {
  Scene scene = makeCornell();
  const Viewpoint& view = scene.viewpoints.front();
  Settings compute = small("cornell", Tracer::Compute);
  Settings rt = small("cornell", Tracer::Rt);
  std::vector<glm::vec3> computeWave = renderRadiance(ctx(), scene, compute, view);
  std::vector<glm::vec3> rtWave = renderRadiance(ctx(), scene, rt, view);
  Settings rtMega = rt;
  rtMega.kernel = Kernel::Megakernel;
  std::vector<glm::vec3> rtMegaImage = renderRadiance(ctx(), scene, rtMega, view);
  Settings otherSeed = rt;
  otherSeed.seed = 77;
  std::vector<glm::vec3> rtWave2 = renderRadiance(ctx(), scene, otherSeed, view);
  Settings computeOtherSeed = compute;
  computeOtherSeed.seed = 77;
  std::vector<glm::vec3> computeWave2 = renderRadiance(ctx(), scene, computeOtherSeed, view);

  ASSERT_GT(moments(rtWave).mean, 0.01) << "the Cornell box must not render black with the rt tracer";
  double rtNoise = relativeMse(rtWave2, rtWave);
  double computeNoise = relativeMse(computeWave2, computeWave);
  EXPECT_GT(rtNoise, 0.0);
  const double noise = std::min(rtNoise, computeNoise);
  expectAgreement(rtWave, computeWave, noise, "rt wavefront vs compute wavefront");
  expectAgreement(rtMegaImage, computeWave, noise, "rt megakernel vs compute wavefront");
  expectAgreement(rtMegaImage, rtWave, noise, "rt megakernel vs rt wavefront");
}

// The temple, with its sky and emissive triangles: shadow rays toward both kinds of light.
TEST_F(RtTracerTest, RtAgreesWithComputeOnTheTemple) {
  Scene scene = makeTemple();
  const Viewpoint& view = *scene.findViewpoint("openings");
  Settings compute = small("temple", Tracer::Compute);
  Settings rt = small("temple", Tracer::Rt);
  std::vector<glm::vec3> c = renderRadiance(ctx(), scene, compute, view);
  std::vector<glm::vec3> r = renderRadiance(ctx(), scene, rt, view);
  rt.seed = 77;
  std::vector<glm::vec3> r2 = renderRadiance(ctx(), scene, rt, view);
  expectAgreement(r, c, relativeMse(r2, r), "rt vs compute, temple openings");
}

// The central invariant within the rt tracer: every key strategy with either sort renders the unsorted rt
// image bit for bit (the driver's traversal of one ray does not depend on its thread either).
TEST_F(RtTracerTest, RtEveryStrategyAndSortRendersTheUnsortedRtImage) {
  Scene scene = makeTemple();
  const Viewpoint& view = *scene.findViewpoint("hall");
  Settings base;
  base.tracer = Tracer::Rt;
  base.width = 37;
  base.height = 19;
  base.bounces = 4;
  base.sppPerFrame = 2;
  base.frames = 2;
  std::vector<glm::vec3> unsorted = renderRadiance(ctx(), scene, base, view);
  ASSERT_GT(moments(unsorted).mean, 0.0);
  for (SortAlgorithm sort : {SortAlgorithm::Radix, SortAlgorithm::Bitonic})
    for (KeyStrategy strategy : allKeyStrategies()) {
      if (strategy == KeyStrategy::None) continue;
      Settings s = base;
      s.strategy = strategy;
      s.sort = sort;
      ASSERT_TRUE(s.sorts());
      std::vector<glm::vec3> sorted = renderRadiance(ctx(), scene, s, view);
      ASSERT_EQ(sorted.size(), unsorted.size());
      EXPECT_EQ(0, std::memcmp(sorted.data(), unsorted.data(), sorted.size() * sizeof(glm::vec3)))
          << toString(strategy) << " with " << toString(sort) << " changed the rt image";
    }
}

// Statistics of our traversal loop are reported as unavailable, not as zeros; rays are still counted.
TEST_F(RtTracerTest, RtStatisticsSayWhatIsNotAvailable) {
  Scene scene = makeTemple();
  Settings s = small("temple", Tracer::Rt);
  s.countSimt = true;
  PathTracer tracer(ctx(), scene, s, *scene.findViewpoint("hall"));
  tracer.setDetailedStats(true);
  const FrameStats& st = tracer.renderFrame();
  EXPECT_EQ(st.traversalStatsUnavailable, "not available with the rt tracer");
  EXPECT_GT(st.raysTraced, uint64_t(s.width) * s.height);
  EXPECT_GT(st.accelerationStructureBytes, 0u);
  for (const BounceStats& b : st.bounces) {
    EXPECT_LT(b.simtEfficiency, 0.0);
    EXPECT_LT(b.virtualWarpEfficiency, 0.0);
  }
}

// Switching tracers on one PathTracer (the window, the bench) builds the acceleration structures on demand.
TEST_F(RtTracerTest, RtSwitchingTracersMidAccumulation) {
  Scene scene = makeCornell();
  Settings s = small("cornell", Tracer::Compute);
  PathTracer tracer(ctx(), scene, s, scene.viewpoints.front());
  tracer.renderFrame();
  s.tracer = Tracer::Rt;
  tracer.applySettings(s);
  tracer.renderFrame();
  s.tracer = Tracer::Compute;
  tracer.applySettings(s);
  tracer.renderFrame();
  EXPECT_EQ(tracer.accumulatedFrames(), 3u);
  EXPECT_GT(moments(tracer.readRadiance()).mean, 0.01);
}

// SER runs only where VK_NV_ray_tracing_invocation_reorder is (not lavapipe): with and without the hint
// the image agrees with the rt megakernel's.
TEST_F(RtTracerTest, RtSerAgreesWithoutSer) {
  Settings ser;
  ser.tracer = Tracer::Rt;
  ser.ser = Ser::On;
  if (std::string why = unsupportedSettings(ctx().info(), ser); !why.empty()) GTEST_SKIP() << why;
  Scene scene = makeCornell();
  const Viewpoint& view = scene.viewpoints.front();
  Settings mega = small("cornell", Tracer::Rt);
  mega.kernel = Kernel::Megakernel;
  std::vector<glm::vec3> plain = renderRadiance(ctx(), scene, mega, view);
  Settings other = mega;
  other.seed = 77;
  const double noise = relativeMse(renderRadiance(ctx(), scene, other, view), plain);
  for (Ser mode : {Ser::On, Ser::Hint}) {
    Settings s = mega;
    s.ser = mode;
    s.strategy = KeyStrategy::TwoPoint;
    expectAgreement(renderRadiance(ctx(), scene, s, view), plain, noise, toString(mode).c_str());
  }
}

}  // namespace raylab::test
