// Whole-image properties of the renderer on the test device: determinism for a seed, and agreement of
// the megakernel baseline with the wavefront.
#include <cstring>

#include <gtest/gtest.h>

#include "tests/gpu_test.h"
#include "tests/render_helpers.h"
#include "scenes/procedural.h"

namespace raylab::test {

class RenderConsistency : public GpuTest {
 protected:
  Settings small(const char* scene) {
    Settings s;
    s.scene = scene;
    s.width = 40;
    s.height = 24;
    s.bounces = 4;
    s.frames = 2;
    return s;
  }
};

TEST_F(RenderConsistency, SameSeedGivesTheSameImageBitForBit) {
  Scene scene = makeTemple();
  Settings s = small("temple");
  const Viewpoint& view = *scene.findViewpoint("hall");
  std::vector<glm::vec3> a = renderRadiance(ctx(), scene, s, view);
  std::vector<glm::vec3> b = renderRadiance(ctx(), scene, s, view);
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(0, std::memcmp(a.data(), b.data(), a.size() * sizeof(glm::vec3)));
  s.seed = 2;
  std::vector<glm::vec3> c = renderRadiance(ctx(), scene, s, view);
  EXPECT_NE(0, std::memcmp(a.data(), c.data(), a.size() * sizeof(glm::vec3))) << "the seed must matter";
}

// The trace and the megakernel count traversal steps only on frames that read them (detailed statistics, a
// heatmap): counting changes no pixel, and a detailed frame still reports the steps.
TEST_F(RenderConsistency, StepsAreCountedOnlyWhereReadAndChangeNoPixel) {
  Scene scene = makeTemple();
  const Viewpoint& view = *scene.findViewpoint("hall");
  for (Kernel kernel : {Kernel::Wavefront, Kernel::Megakernel}) {
    Settings s = small("temple");
    s.kernel = kernel;
    s.compaction = Compaction::None;
    const std::string what = toString(kernel);
    PathTracer plain(ctx(), scene, s, view), detailed(ctx(), scene, s, view);
    detailed.setDetailedStats(true);
    FrameStats counted;
    for (uint32_t f = 0; f < s.frames; ++f) {
      plain.renderFrame();
      counted = detailed.renderFrame();
    }
    expectSameImage(plain.readRadiance(), detailed.readRadiance(), what + ": counting steps");
    ASSERT_FALSE(counted.bounces.empty()) << what;
    EXPECT_GT(counted.bounces[0].meanTraversalSteps, 1.0) << what << ": a detailed frame counts its steps";
  }
}

// Statistical agreement: the two kernels run the same estimator with the same random streams, so their
// images must differ by no more than two independent renders of one kernel do (relative MSE between
// seeds), and their means must agree within four standard errors.
TEST_F(RenderConsistency, MegakernelAgreesWithWavefront) {
  Scene scene = makeCornell();
  Settings s = small("cornell");
  s.frames = 6;
  s.sppPerFrame = 2;
  const Viewpoint& view = scene.viewpoints.front();
  std::vector<glm::vec3> wave = renderRadiance(ctx(), scene, s, view);
  Settings m = s;
  m.kernel = Kernel::Megakernel;
  std::vector<glm::vec3> mega = renderRadiance(ctx(), scene, m, view);
  Settings other = s;
  other.seed = 77;
  std::vector<glm::vec3> wave2 = renderRadiance(ctx(), scene, other, view);

  double noise = relativeMse(wave2, wave);
  double kernelGap = relativeMse(mega, wave);
  EXPECT_GT(noise, 0.0);
  EXPECT_LE(kernelGap, 1.5 * noise) << "kernel gap " << kernelGap << " vs seed noise " << noise;
  ImageMoments a = moments(wave), b = moments(mega);
  EXPECT_GT(a.mean, 0.01) << "the Cornell box must not render black";
  EXPECT_NEAR(a.mean, b.mean, 4.0 * std::hypot(a.standardError, b.standardError));
}

}  // namespace raylab::test
