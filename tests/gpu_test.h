// Base fixture of every GPU test: one Vulkan context on the default device (lavapipe where there is no GPU)
// with the Khronos validation layer on (synchronization validation, or GPU-assisted with
// RAYLAB_VALIDATE=gpu-av); any validation error during the test fails it.
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
      options.validation = validationMode();
      options.quiet = true;
      return std::make_unique<VulkanContext>(options);
    }();
    return *context;
  }
  // RAYLAB_VALIDATE chooses the checks (ctest sets 1: synchronization validation; the gpu-av ctest sets
  // gpu-av); unset, the tests still validate, with sync.
  static ValidationMode validationMode() {
    static const ValidationMode mode = [] {
      ValidationMode m = validationModeFromEnvironment();
      return m == ValidationMode::Off ? ValidationMode::Sync : m;
    }();
    return mode;
  }
  void SetUp() override { errorsBefore_ = ctx().validationErrors(); }
  void TearDown() override {
    EXPECT_EQ(ctx().validationErrors(), errorsBefore_ + errorsExpected_) << "the validation layer reported errors";
  }
  // A test that provokes errors on purpose (proof that a check is on) says how many it counted.
  void expectValidationErrors(uint32_t count) { errorsExpected_ = count; }

 private:
  uint32_t errorsBefore_ = 0;
  uint32_t errorsExpected_ = 0;
};

}  // namespace raylab::test
