// The one conversion of a thread count into a dispatch size (renderer/vk/dispatch_size.h): rows of at most
// the device's groups in x, a short last row, and a clear error past the device's rows.
#include <gtest/gtest.h>

#include "renderer/vk/dispatch_size.h"
#include "renderer/vk/vk_check.h"

namespace raylab {

TEST(DispatchSize, OneRowUpToTheLimit) {
  EXPECT_EQ(dispatchSizeFor(0, 64, 65535, 65535).x, 0u);
  DispatchSize one = dispatchSizeFor(1, 64, 65535, 65535);
  EXPECT_EQ(one.x, 1u);
  EXPECT_EQ(one.y, 1u);
  DispatchSize full = dispatchSizeFor(65535ull * 64, 64, 65535, 65535);
  EXPECT_EQ(full.x, 65535u);
  EXPECT_EQ(full.y, 1u);
}

TEST(DispatchSize, RowsPastTheLimit) {
  // 2048x2048 paths at 64 a group: 65536 groups, one more than lavapipe's 65535 in x.
  DispatchSize paths = dispatchSizeFor(2048ull * 2048, 64, 65535, 65535);
  EXPECT_EQ(paths.x, 65535u);
  EXPECT_EQ(paths.y, 2u);
  // 8192x8192 (the settings' largest frame): 2^20 groups in 17 rows, covering every thread.
  DispatchSize largest = dispatchSizeFor(8192ull * 8192, 64, 65535, 65535);
  EXPECT_GE(uint64_t(largest.x) * largest.y * 64, 8192ull * 8192);
  EXPECT_LT(uint64_t(largest.x) * (largest.y - 1) * 64, 8192ull * 8192) << "no row is wholly past the count";
  DispatchSize shortRows = dispatchSizeFor(1406, 64, 3, 65535);  // 22 groups
  EXPECT_EQ(shortRows.x, 3u);
  EXPECT_EQ(shortRows.y, 8u);
}

TEST(DispatchSize, TooManyRowsThrow) { EXPECT_THROW(dispatchSizeFor(1000, 1, 10, 99), VulkanError); }

}  // namespace raylab
