// Proof that the validation layer's extra checks are on: each test makes the mistake its check exists for,
// on purpose, and expects it counted as a validation error (the fixture then accepts exactly that many).
// Synchronization validation runs in every GPU test (RAYLAB_VALIDATE=1); GPU-assisted validation in the
// gpu-av ctest (RAYLAB_VALIDATE=gpu-av, tests/CMakeLists.txt). Each test skips, saying so, in the other mode.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "renderer/vk/compute_pipeline.h"
#include "renderer/vk/gpu_buffer.h"
#include "shaders/sort_types.h"
#include "tests/gpu_test.h"

namespace raylab::test {
namespace {

// sort_copy.comp copies `count` keys and values between four device addresses: the smallest stage whose
// buffers the test chooses freely. A count of zero touches no memory.
gpu::SortCopyPush copyPush(const GpuBuffer& in, const GpuBuffer& out, uint32_t count) {
  return gpu::SortCopyPush{in.address(), in.address(), out.address(), out.address(), count, 0u, 0u};
}

}  // namespace

class ValidationChecks : public GpuTest {};

// The renderer's shaders reach every buffer through device addresses, which synchronization validation
// does not track (a dispatch that writes through an address followed by one that reads it, with no barrier,
// is not reported); what it does see is every transfer command and every indirect dispatch's argument
// read. So the hazard left in here is the renderer's own pattern: indirect arguments written by a transfer
// (PathTracer::recordFrameBlock's vkCmdUpdateBuffer of the live blocks), then a dispatch that reads them,
// with the barrier between the two left out.
TEST_F(ValidationChecks, SyncValidationReportsAMissingBarrier) {
  if (validationMode() != ValidationMode::Sync) GTEST_SKIP() << "needs RAYLAB_VALIDATE=1 (synchronization validation)";
  ComputePipeline copy(ctx(), "sort_copy", sizeof(gpu::SortCopyPush));
  GpuBuffer args(ctx(), 3 * sizeof(uint32_t));
  GpuBuffer data(ctx(), 64);
  const uint32_t before = ctx().validationErrors();
  ctx().submitAndWait([&](VkCommandBuffer cmd) {
    const uint32_t oneGroup[3] = {1u, 1u, 1u};
    vkCmdUpdateBuffer(cmd, args.handle(), 0, sizeof(oneGroup), oneGroup);
    // computeBarrier(cmd) belongs here.
    copy.dispatchIndirect(cmd, copyPush(data, data, 0u), args.handle(), 0);
  });
  const uint32_t reported = ctx().validationErrors() - before;
  EXPECT_GE(reported, 1u) << "synchronization validation did not report the missing barrier";
  EXPECT_NE(ctx().lastValidationError().find("SYNC-HAZARD-READ"), std::string::npos) << ctx().lastValidationError();
  expectValidationErrors(reported);
}

// The same pair with the barrier in place is clean: the hazard above is the missing barrier, nothing else.
TEST_F(ValidationChecks, SyncValidationAcceptsTheBarrier) {
  ComputePipeline copy(ctx(), "sort_copy", sizeof(gpu::SortCopyPush));
  GpuBuffer args(ctx(), 3 * sizeof(uint32_t));
  GpuBuffer data(ctx(), 64);
  ctx().submitAndWait([&](VkCommandBuffer cmd) {
    const uint32_t oneGroup[3] = {1u, 1u, 1u};
    vkCmdUpdateBuffer(cmd, args.handle(), 0, sizeof(oneGroup), oneGroup);
    computeBarrier(cmd);
    copy.dispatchIndirect(cmd, copyPush(data, data, 0u), args.handle(), 0);
  });
}

// A read through a device address past the end of its buffer: 1024 keys copied out of a buffer of 16.
// GPU-assisted validation instruments the shader, checks the address against every live buffer's range and
// reports the access.
TEST_F(ValidationChecks, GpuAssistedValidationReportsAnOutOfBoundsAddress) {
  if (validationMode() != ValidationMode::GpuAssisted)
    GTEST_SKIP() << "needs RAYLAB_VALIDATE=gpu-av (GPU-assisted validation)";
  ComputePipeline copy(ctx(), "sort_copy", sizeof(gpu::SortCopyPush));
  GpuBuffer small(ctx(), 16 * sizeof(uint32_t));
  GpuBuffer large(ctx(), 1024 * sizeof(uint32_t));
  const uint32_t before = ctx().validationErrors();
  ctx().submitAndWait([&](VkCommandBuffer cmd) { copy.dispatchGroups(cmd, copyPush(small, large, 1024u), 1); });
  const uint32_t reported = ctx().validationErrors() - before;
  EXPECT_GE(reported, 1u) << "GPU-assisted validation did not report the out-of-bounds device address";
  std::printf("[ gpu-av   ] reported: %s\n", ctx().lastValidationError().c_str());
  expectValidationErrors(reported);
}

}  // namespace raylab::test
