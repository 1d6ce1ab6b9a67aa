// The first bounce's slot order (shaders/camera_order.h, the C++ side of the header the shaders include): a
// bijection of the pixels at every size, tiles of at most 8x4 pixels, so one 32-slot warp of camera rays covers
// one compact patch.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "shaders/camera_order.h"

namespace raylab {
namespace {

TEST(CameraOrder, EverySizeIsABijectionOfPixelsAndSamples) {
  for (uint32_t w : {1u, 2u, 7u, 8u, 9u, 23u, 64u, 100u})
    for (uint32_t h : {1u, 3u, 4u, 5u, 13u, 32u})
      for (uint32_t spp : {1u, 3u}) {
        std::vector<int> seen(size_t(w) * h * spp, 0);
        for (uint32_t slot = 0; slot < seen.size(); ++slot) {
          const uint32_t id = gpu::cameraPathOfSlot(slot, w, h, spp);
          ASSERT_LT(id, seen.size()) << w << "x" << h << " spp " << spp << " slot " << slot;
          seen[id]++;
          EXPECT_EQ(id % spp, slot % spp) << "a pixel's samples stay adjacent";
        }
        EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; })) << w << "x" << h;
      }
}

// Where the width is a multiple of 8 (the usual sizes), every aligned 32 slots above the last band are one
// aligned 8x4 tile; elsewhere a warp straddles at most two tiles.
void expectCompactWarps(uint32_t w, uint32_t h) {
  for (uint32_t warp = 0; warp * 32 < w * h; ++warp) {
    uint32_t x0 = w, x1 = 0, y0 = h, y1 = 0;
    for (uint32_t slot = warp * 32; slot < std::min(w * h, warp * 32 + 32); ++slot) {
      const uint32_t p = gpu::cameraPixelOfSlot(slot, w, h);
      x0 = std::min(x0, p % w), x1 = std::max(x1, p % w), y0 = std::min(y0, p / w), y1 = std::max(y1, p / w);
    }
    if (w % 8 == 0 && y0 < h / 4 * 4) {
      EXPECT_EQ(x1 - x0, 7u) << w << "x" << h << " warp " << warp;
      EXPECT_EQ(y1 - y0, 3u) << w << "x" << h << " warp " << warp;
      EXPECT_EQ(x0 % 8, 0u);
      EXPECT_EQ(y0 % 4, 0u);
    } else {
      EXPECT_LE(y1 - y0, 7u) << w << "x" << h << " warp " << warp;
    }
  }
}

TEST(CameraOrder, WarpsCoverCompactTiles) {
  expectCompactWarps(96, 30);
  expectCompactWarps(100, 30);
  expectCompactWarps(1280, 720);
  EXPECT_EQ(gpu::cameraPixelOfSlot(0, 96, 30), 0u);
  EXPECT_EQ(gpu::cameraPixelOfSlot(8, 96, 30), 96u);  // row-major in the tile: slot 8 starts its second row
  EXPECT_EQ(gpu::cameraPixelOfSlot(32, 96, 30), 8u);  // the next tile
}

}  // namespace
}  // namespace raylab
