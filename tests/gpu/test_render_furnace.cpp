// White furnace: inside a closed sphere whose every triangle has albedo a and emission e (pure Lambert),
// each of the B bounces adds e * a^k, so the mean radiance is e * sum_{k<B} a^k exactly. The tolerance is
// five standard errors of the image mean (estimated from the pixel spread, so it shrinks with the sample
// count) plus float slack.
#include <gtest/gtest.h>

#include "tests/gpu_test.h"
#include "tests/render_helpers.h"
#include "scenes/procedural.h"

namespace raylab::test {

class FurnaceTest : public GpuTest, public ::testing::WithParamInterface<std::tuple<float, float, uint32_t, Kernel, BvhLayout>> {};

TEST_P(FurnaceTest, MeanMatchesAnalyticValue) {
  auto [albedo, emission, bounces, kernel, bvh] = GetParam();
  Scene scene = makeFurnace(albedo, emission, 3);
  Settings s;
  s.width = 48;
  s.height = 32;
  s.bounces = bounces;
  s.sppPerFrame = 4;
  s.frames = 4;
  s.kernel = kernel;
  s.bvh = bvh;
  std::vector<glm::vec3> img = renderRadiance(ctx(), scene, s, scene.viewpoints.front());
  double expected = 0.0;
  for (uint32_t k = 0; k < bounces; ++k) expected += emission * std::pow(albedo, double(k));
  ImageMoments m = moments(img);
  double tolerance = 5.0 * m.standardError + 1e-4 * expected;
  EXPECT_NEAR(m.mean, expected, tolerance) << "standard error " << m.standardError;
  // A furnace without variance would make the tolerance meaningless; make sure it is tight.
  EXPECT_LT(tolerance, 0.02 * expected);
}

INSTANTIATE_TEST_SUITE_P(Furnace, FurnaceTest,
                         ::testing::Values(std::make_tuple(0.5f, 0.5f, 4u, Kernel::Wavefront, BvhLayout::Binary),
                                           std::make_tuple(0.8f, 0.25f, 8u, Kernel::Wavefront, BvhLayout::Binary),
                                           std::make_tuple(0.5f, 0.5f, 4u, Kernel::Megakernel, BvhLayout::Binary),
                                           std::make_tuple(0.3f, 1.0f, 1u, Kernel::Wavefront, BvhLayout::Binary),
                                           // The wide BVH: every ray inside the closed sphere must hit it.
                                           std::make_tuple(0.8f, 0.25f, 8u, Kernel::Wavefront, BvhLayout::Wide),
                                           std::make_tuple(0.5f, 0.5f, 4u, Kernel::Megakernel, BvhLayout::Wide)));

}  // namespace raylab::test
