// Virtual warp efficiency as renderer/warp_efficiency.h defines it: per warp of W consecutive threads sum(n_i) / (W * max n_i),
// the frame weighted by W * max n_i. Values worked out by hand.
#include <gtest/gtest.h>

#include <vector>

#include "renderer/warp_efficiency.h"

namespace raylab {

TEST(WarpEfficiency, UniformWorkIsFullyEfficient) {
  std::vector<uint32_t> steps(64, 7);
  WarpEfficiency w = virtualWarpEfficiency(steps.data(), steps.size(), 32);
  EXPECT_DOUBLE_EQ(w.efficiency, 1.0);
  EXPECT_DOUBLE_EQ(w.meanSteps, 7.0);
}

TEST(WarpEfficiency, WarpsAreWeightedByTheirSlots) {
  // Warp 0 (W = 4): 4, 0, 0, 0 -> 4 of 16 slots. Warp 1: 2, 2, 2, 2 -> 8 of 8. Frame: 12 / 24.
  std::vector<uint32_t> steps{4, 0, 0, 0, 2, 2, 2, 2};
  WarpEfficiency w = virtualWarpEfficiency(steps.data(), steps.size(), 4);
  EXPECT_DOUBLE_EQ(w.efficiency, 0.5);
  EXPECT_DOUBLE_EQ(w.meanSteps, 1.5);
}

TEST(WarpEfficiency, PartialLastWarpStillOccupiesAllLanes) {
  // 5 threads, W = 4: warp 0 is 1,1,1,1 (4 of 4), warp 1 is 3 alone (3 of 12). Frame: 7 / 16.
  std::vector<uint32_t> steps{1, 1, 1, 1, 3};
  EXPECT_DOUBLE_EQ(virtualWarpEfficiency(steps.data(), steps.size(), 4).efficiency, 7.0 / 16.0);
}

TEST(WarpEfficiency, NoWorkAndNoThreads) {
  std::vector<uint32_t> idle(40, 0);
  EXPECT_DOUBLE_EQ(virtualWarpEfficiency(idle.data(), idle.size(), 32).efficiency, 1.0);
  EXPECT_DOUBLE_EQ(virtualWarpEfficiency(nullptr, 0, 32).efficiency, 1.0);
}

}  // namespace raylab
