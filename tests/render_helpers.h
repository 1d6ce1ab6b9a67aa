// Small helpers for tests that render whole images on the test device.
#pragma once

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "renderer/image_metrics.h"
#include "renderer/path_tracer.h"
#include "renderer/vk/vk_context.h"

namespace raylab::test {

// Default settings at a small size (tests pick sizes that are no multiple of a group or warp size).
inline Settings smallFrame(uint32_t width, uint32_t height, uint32_t bounces) {
  Settings s;
  s.width = width;
  s.height = height;
  s.bounces = bounces;
  return s;
}

// Renders settings.frames frames and returns the accumulated mean radiance per pixel.
inline std::vector<glm::vec3> renderRadiance(const VulkanContext& ctx, const Scene& scene, const Settings& settings,
                                             const Viewpoint& view) {
  PathTracer tracer(ctx, scene, settings, view);
  for (uint32_t f = 0; f < settings.frames; ++f) tracer.renderFrame();
  return tracer.readRadiance();
}

// Renders one frame in steps, a growing number per submission (1, 2, 3, ... steps, one submission each, as
// the window does) and returns the accumulated radiance; `submissions` gets how many there were.
inline std::vector<glm::vec3> renderRadianceInSteps(const VulkanContext& ctx, const Scene& scene, const Settings& settings,
                                                    const Viewpoint& view, uint32_t& submissions) {
  PathTracer parts(ctx, scene, settings, view);
  submissions = 0;
  for (const FrameStats* done = nullptr; !done; ++submissions) {
    ctx.submitAndWait([&](VkCommandBuffer cmd) { parts.recordSteps(cmd, 1 + submissions); });
    done = parts.finishSteps(1.0);
  }
  return parts.readRadiance();
}

// Bit for bit: no tolerance. `what` names the variant in the failure message.
inline void expectSameImage(const std::vector<glm::vec3>& got, const std::vector<glm::vec3>& want, const std::string& what) {
  ASSERT_EQ(got.size(), want.size()) << what;
  EXPECT_EQ(0, std::memcmp(got.data(), want.data(), got.size() * sizeof(glm::vec3))) << what << " changed the image";
}

struct ImageMoments {
  double mean = 0.0;
  double standardError = 0.0;  // of the mean, from the spread of the pixels
};

// Mean of all channels of all pixels, and its standard error estimated from the pixel variance.
inline ImageMoments moments(const std::vector<glm::vec3>& img) {
  ImageMoments m;
  double sum = 0.0, sum2 = 0.0;
  for (const glm::vec3& p : img) {
    double v = (p.x + p.y + p.z) / 3.0;
    sum += v;
    sum2 += v * v;
  }
  double n = static_cast<double>(img.size());
  m.mean = sum / n;
  double var = std::max(0.0, sum2 / n - m.mean * m.mean);
  m.standardError = std::sqrt(var / n);
  return m;
}

}  // namespace raylab::test
