// Base fixture of every GPU test: one Vulkan context on the default device (lavapipe where there is no GPU)
// with the Khronos validation layer on; any validation error during the test fails it.
#pragma once

// The CPU test binary runs again under LeakSanitizer, which the Vulkan driver's exit-time leak would fail.
#ifdef RAYLAB_CPU_TESTS
#error "a test that needs a Vulkan device belongs in tests/gpu/"
#endif

#include <memory>

#include <gtest/gtest.h>

#include "renderer/vk/vk_context.h"

namespace raylab::test {

class GpuTest : public ::testing::Test {
 protected:
  static VulkanContext& ctx() {
    static std::unique_ptr<VulkanContext> context = [] {
      ContextOptions options;
      options.validate = true;
      options.quiet = true;
      return std::make_unique<VulkanContext>(options);
    }();
    return *context;
  }
  void SetUp() override { errorsBefore_ = ctx().validationErrors(); }
  void TearDown() override {
    EXPECT_EQ(ctx().validationErrors(), errorsBefore_) << "the validation layer reported errors";
  }

 private:
  uint32_t errorsBefore_ = 0;
};

}  // namespace raylab::test
