// Proof that the validation layer's extra checks are on: each test makes the mistake its check exists for,
// on purpose, and expects it counted as a validation error (the fixture then accepts exactly that many).
// Synchronization validation runs in every GPU test (RAYLAB_VALIDATE=1); GPU-assisted validation in the
// gpu-av ctest (RAYLAB_VALIDATE=gpu-av, tests/CMakeLists.txt). Each test skips, saying so, in the other mode.
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "renderer/vk/compute_pipeline.h"
#include "renderer/vk/gpu_buffer.h"
#include "renderer/vk/validation_layer.h"
#include "renderer/vk/vk_context.h"
#include "shaders/sort_types.h"
#include "tests/gpu_test.h"

namespace raylab::test {
namespace {

// sort_copy.comp copies `count` keys and values between four device addresses: the smallest stage whose
// buffers the test chooses freely. A count of zero touches no memory.
gpu::SortCopyPush copyPush(VkDeviceAddress in, VkDeviceAddress out, uint32_t count) {
  return gpu::SortCopyPush{in, in, out, out, count, 0u, 0u};
}
gpu::SortCopyPush copyPush(const GpuBuffer& in, const GpuBuffer& out, uint32_t count) {
  return copyPush(in.address(), out.address(), count);
}

// A 64-byte buffer alone at the start of a 1 MiB memory allocation. Reading past its end stays inside
// memory the device has mapped (no fault on a real GPU), yet lies outside every buffer's range, which is what
// GPU-AV checks a device address against.
constexpr VkDeviceSize kLoneBytes = 64, kLoneMemoryBytes = 1 << 20;
GpuBuffer loneBuffer(const VulkanContext& ctx) {
  return GpuBuffer(ctx, kLoneBytes, MemoryKind::DeviceLocal, 0, kLoneMemoryBytes);
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

// GPU-AV's reports of a planted mistake come and go on Debian 13's layer 1.4.309 over lavapipe: a
// submission that plants one is reported (6 messages) or not at all, with nothing arriving later (waiting 10 s
// after the fence brought nothing). In 20 processes the first report came after 1 to 27 submissions (median
// 2). So each proof plants its mistake in up to kAttempts submissions, each with fresh buffers, and asks for a
// report from at least one; it prints how many it took, and a layer that never checks still fails. A clean
// gpu_av.subset run is therefore evidence, not proof, that the renderer's accesses are in bounds.
constexpr int kAttempts = 256;

template <typename Plant>
uint32_t plantedReports(const VulkanContext& ctx, const char* what, Plant plant) {
  uint32_t reported = 0;
  int attempts = 0;
  while (attempts < kAttempts && reported == 0) {
    const uint32_t before = ctx.validationErrors();
    plant();
    ++attempts;
    reported += ctx.validationErrors() - before;
  }
  std::printf("[ gpu-av   ] %s: %u report(s) after %d of at most %d attempts: %s\n", what, reported, attempts,
              kAttempts, ctx.lastValidationError().c_str());
  return reported;
}

// A read through a device address past the end of its buffer: 1024 keys copied out of a buffer of 16 (a lone
// buffer in a larger allocation, so the overrun is outside every buffer on any device). GPU-assisted
// validation instruments the shader, checks the address against every live buffer's range and reports the
// access.
TEST_F(ValidationChecks, GpuAssistedValidationReportsAnOutOfBoundsAddress) {
  if (validationMode() != ValidationMode::GpuAssisted)
    GTEST_SKIP() << "needs RAYLAB_VALIDATE=gpu-av (GPU-assisted validation)";
  ComputePipeline copy(ctx(), "sort_copy", sizeof(gpu::SortCopyPush));
  static_assert(kLoneBytes == 16 * sizeof(uint32_t) && 1024 * sizeof(uint32_t) < kLoneMemoryBytes);
  const uint32_t reported = plantedReports(ctx(), "overrun", [&] {
    GpuBuffer small = loneBuffer(ctx());
    GpuBuffer large(ctx(), 1024 * sizeof(uint32_t));
    ctx().submitAndWait([&](VkCommandBuffer cmd) { copy.dispatchGroups(cmd, copyPush(small.address(), large.address(), 1024u), 1); });
  });
  EXPECT_GE(reported, 1u) << "GPU-assisted validation did not report the out-of-bounds device address";
  expectValidationErrors(reported);
}

// A read through a misaligned device address, inside its buffer: 16 keys copied from two bytes past the start
// of a buffer of 1024 (sort_copy's loads are 4-byte aligned). GPU-AV checks an access's alignment without its
// table of buffer ranges, so this proof does not depend on where the driver places buffers.
TEST_F(ValidationChecks, GpuAssistedValidationReportsAMisalignedAddress) {
  if (validationMode() != ValidationMode::GpuAssisted)
    GTEST_SKIP() << "needs RAYLAB_VALIDATE=gpu-av (GPU-assisted validation)";
  // Debian 12's layer checks addresses against buffer ranges only (its 256 submissions went unreported).
  if (validationLayerVersion() <= VK_MAKE_API_VERSION(0, 1, 3, 239))
    GTEST_SKIP() << "GPU-AV of layer 1.3.239 does not check the alignment of device-address accesses";
  ComputePipeline copy(ctx(), "sort_copy", sizeof(gpu::SortCopyPush));
  const uint32_t reported = plantedReports(ctx(), "misaligned read", [&] {
    GpuBuffer in(ctx(), 1024 * sizeof(uint32_t));
    GpuBuffer out(ctx(), 1024 * sizeof(uint32_t));
    ctx().submitAndWait([&](VkCommandBuffer cmd) { copy.dispatchGroups(cmd, copyPush(in.address() + 2, out.address(), 16u), 1); });
  });
  EXPECT_GE(reported, 1u) << "GPU-assisted validation did not report the misaligned device address";
  expectValidationErrors(reported);
}

}  // namespace raylab::test
