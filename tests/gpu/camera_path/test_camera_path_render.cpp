// Rendering along a camera path (app/camera_path/render_camera_path.h): every path frame, before and after a cut, is
// the unsorted frame bit for bit whatever the key strategy (the central invariant under a moving camera), and
// a camera move, a cut included, restarts the accumulation and nothing else: the length cache keeps what it
// learned and the sort policy keeps its measured costs (SettingsChange::cameraMove); every path frame reports
// the cache's resets.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/camera_path/camera_path.h"
#include "scenes/procedural.h"
#include "tests/gpu_test.h"
#include "tests/render_helpers.h"

namespace raylab::test {
namespace {

const glm::vec3 kUp(0.0f, 1.0f, 0.0f);

// tests/data/camera_paths/cut_at_2.json: the hall, stepping back, then a cut to the openings at frame 2.
CameraPath cutAt2() { return loadCameraPath(RAYLAB_SOURCE_DIR "/tests/data/camera_paths/cut_at_2.json", kUp); }

// Each path frame's radiance, rendered as `raylab render --camera-path` renders it.
std::vector<std::vector<glm::vec3>> renderPath(const VulkanContext& ctx, const Scene& scene, const Settings& s,
                                               const CameraPath& path) {
  PathTracer tracer(ctx, scene, s, cameraAt(path, 0, kUp).view);
  std::vector<std::vector<glm::vec3>> frames;
  for (uint32_t f = 0; f < path.frames; ++f) {
    tracer.setCamera(cameraAt(path, f, kUp).view);
    tracer.renderFrame();
    frames.push_back(tracer.readRadiance());
  }
  return frames;
}

class CameraPathRender : public GpuTest {};

TEST_F(CameraPathRender, EveryPathFrameSortedIsTheUnsortedFrame) {
  const Scene scene = makeTemple();
  const CameraPath path = cutAt2();
  ASSERT_EQ(path.frames, 6u);
  Settings base = smallFrame(48, 24, 3);
  const std::vector<std::vector<glm::vec3>> unsorted = renderPath(ctx(), scene, base, path);
  // The frames differ from each other (the camera moved; a cut jumped), so equal images mean something.
  EXPECT_NE(0, std::memcmp(unsorted[1].data(), unsorted[2].data(), unsorted[1].size() * sizeof(glm::vec3)));
  EXPECT_NE(0, std::memcmp(unsorted[0].data(), unsorted[1].data(), unsorted[0].size() * sizeof(glm::vec3)));
  for (KeyStrategy strategy : {KeyStrategy::TwoPoint, KeyStrategy::Average}) {
    Settings s = base;
    s.strategy = strategy;
    s.sort = SortAlgorithm::Radix;
    ASSERT_TRUE(s.sorts());
    const std::vector<std::vector<glm::vec3>> sorted = renderPath(ctx(), scene, s, path);
    for (uint32_t f = 0; f < path.frames; ++f)
      expectSameImage(sorted[f], unsorted[f], toString(strategy) + " radix, path frame " + std::to_string(f));
  }
}

// What a cut resets: the accumulation (each path frame is one fresh frame of samples, frame index 0), nothing
// else. The length cache keeps the cells the hall taught it (the cut frame's occupancy is at least the frame
// before's, and above that of a cache that saw only the openings), and the auto sort policy keeps counting
// the frames it measured.
TEST_F(CameraPathRender, ACutRestartsTheAccumulationAndKeepsWhatWasLearned) {
  const Scene scene = makeTemple();
  const CameraPath path = cutAt2();
  Settings s = smallFrame(48, 24, 3);
  s.strategy = KeyStrategy::Average;
  s.sort = SortAlgorithm::Radix;
  s.sortPolicy = SortPolicy::Auto;
  PathTracer tracer(ctx(), scene, s, cameraAt(path, 0, kUp).view);
  tracer.setDetailedStats(true);
  std::vector<double> occupancy;
  for (uint32_t f = 0; f < path.frames; ++f) {
    tracer.setCamera(cameraAt(path, f, kUp).view);
    const FrameStats& st = tracer.renderFrame();
    EXPECT_EQ(st.frameIndex, 0u) << f;  // every path frame starts the image again
    EXPECT_EQ(st.samplesPerPixel, s.sppPerFrame) << f;
    EXPECT_EQ(tracer.accumulatedFrames(), 1u) << f;
    EXPECT_EQ(tracer.sortPolicy().framesSeen(), f + 1) << f;  // not reset by the move nor by the cut
    occupancy.push_back(st.lengthCacheOccupancy);
    ASSERT_GT(occupancy.back(), 0.0) << f;
    EXPECT_EQ(st.lengthCacheResets, 0) << f;  // measured every frame; average never resets
  }
  ASSERT_TRUE(cameraAt(path, 2, kUp).cut);
  for (uint32_t f = 1; f < path.frames; ++f) EXPECT_GE(occupancy[f], occupancy[f - 1]) << "the cache lost cells at " << f;

  PathTracer fresh(ctx(), scene, s, cameraAt(path, 2, kUp).view);
  fresh.setDetailedStats(true);
  const double openingsOnly = fresh.renderFrame().lengthCacheOccupancy;
  EXPECT_GT(occupancy[2], openingsOnly) << "the cut frame's cache should still hold the hall's cells";
}

// The Gaussian cache's resets are counted in every path frame, the cut's included: with a threshold below any
// cell's variance every learned bounce resets cells; with none, no frame does.
TEST_F(CameraPathRender, EveryPathFrameReportsItsCacheResets) {
  const Scene scene = makeTemple();
  const CameraPath path = cutAt2();
  Settings s = smallFrame(48, 24, 3);
  s.strategy = KeyStrategy::Gaussian;
  s.sort = SortAlgorithm::Radix;
  for (float threshold : {1e-9f, INFINITY}) {
    s.gaussReset = threshold;
    PathTracer tracer(ctx(), scene, s, cameraAt(path, 0, kUp).view);
    for (uint32_t f = 0; f < path.frames; ++f) {
      tracer.setCamera(cameraAt(path, f, kUp).view);
      const int64_t resets = tracer.renderFrame().lengthCacheResets;
      if (threshold < 1.0f) EXPECT_GT(resets, 0) << "path frame " << f;
      else EXPECT_EQ(resets, 0) << "path frame " << f;
    }
  }
}

}  // namespace
}  // namespace raylab::test
