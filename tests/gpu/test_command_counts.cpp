// A frame's fixed costs (FrameStats::commands, issue 36) are exact: the counts the recorder keeps equal the
// vkCmdDispatch, vkCmdDispatchIndirect and vkCmdPipelineBarrier calls that reached Vulkan (counted by the
// interposers below, whatever code made them: a dispatch added anywhere without being counted fails here),
// and for the unsorted wavefront and the megakernel they follow from the bounces and stages alone.
#include <dlfcn.h>

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "renderer/vk/empty_dispatch.h"
#include "scenes/procedural.h"
#include "shaders/sort_types.h"
#include "tests/gpu_test.h"
#include "tests/render_helpers.h"

namespace {
// The commands that reached Vulkan while armed. The test binary links raylab's libraries statically, so its
// definitions of these entry points take the place of the loader's for every caller in the process; each
// forwards to the loader's own (the next definition), so rendering and validation are unchanged.
struct Issued {
  bool armed = false;
  uint32_t dispatches = 0, indirectDispatches = 0, barriers = 0;
} gIssued;  // one test thread records at a time

template <class Fn>
Fn loaderEntry(const char* name) {
  static_assert(sizeof(Fn) == sizeof(void*));
  void* f = dlsym(RTLD_NEXT, name);
  if (!f) std::abort();
  return reinterpret_cast<Fn>(f);
}
}  // namespace

extern "C" {
VKAPI_ATTR void VKAPI_CALL vkCmdDispatch(VkCommandBuffer cmd, uint32_t x, uint32_t y, uint32_t z) {
  static const auto real = loaderEntry<PFN_vkCmdDispatch>("vkCmdDispatch");
  gIssued.dispatches += gIssued.armed;
  real(cmd, x, y, z);
}
VKAPI_ATTR void VKAPI_CALL vkCmdDispatchIndirect(VkCommandBuffer cmd, VkBuffer buffer, VkDeviceSize offset) {
  static const auto real = loaderEntry<PFN_vkCmdDispatchIndirect>("vkCmdDispatchIndirect");
  gIssued.indirectDispatches += gIssued.armed;
  real(cmd, buffer, offset);
}
VKAPI_ATTR void VKAPI_CALL vkCmdPipelineBarrier(VkCommandBuffer cmd, VkPipelineStageFlags src, VkPipelineStageFlags dst,
                                                VkDependencyFlags flags, uint32_t memoryCount,
                                                const VkMemoryBarrier* memory, uint32_t bufferCount,
                                                const VkBufferMemoryBarrier* buffers, uint32_t imageCount,
                                                const VkImageMemoryBarrier* images) {
  static const auto real = loaderEntry<PFN_vkCmdPipelineBarrier>("vkCmdPipelineBarrier");
  gIssued.barriers += gIssued.armed;
  real(cmd, src, dst, flags, memoryCount, memory, bufferCount, buffers, imageCount, images);
}
}

namespace raylab::test {
namespace {

class CommandCountsTest : public GpuTest {
 protected:
  // One frame of `s` (the second, so the sort policy has costs to plan with), its stats, and what Vulkan got.
  FrameStats render(const Settings& s, Issued& issued, bool detailed = false) {
    PathTracer tracer(ctx(), scene_, s, *scene_.findViewpoint("openings"));
    tracer.setDetailedStats(detailed);
    tracer.renderFrame();
    gIssued = Issued{true};
    FrameStats stats = tracer.renderFrame();
    issued = gIssued;
    gIssued.armed = false;
    return stats;
  }
  void expectExact(const Settings& s, const std::string& what, bool detailed = false) {
    Issued issued;
    const FrameStats stats = render(s, issued, detailed);
    EXPECT_GT(issued.dispatches + issued.indirectDispatches, 0u) << what << ": the interposers saw nothing";
    EXPECT_EQ(stats.commands.directDispatches, issued.dispatches) << what;
    EXPECT_EQ(stats.commands.indirectDispatches, issued.indirectDispatches) << what;
    EXPECT_EQ(stats.commands.barriers, issued.barriers) << what;
    EXPECT_EQ(stats.submissions, 1u) << what;
    // Every command of a frame is recorded inside a stage of renderer/stages.h.
    for (const StageCommands& c : stats.stageCommands) EXPECT_TRUE(findStage(c.stage)) << what << ": '" << c.stage << "'";
  }
  static uint32_t stageDispatches(const FrameStats& stats, const char* stage) {
    for (const StageCommands& c : stats.stageCommands)
      if (c.stage == stage) return c.counts.dispatches();
    return 0;
  }
  Scene scene_ = makeTemple();
};

TEST_F(CommandCountsTest, EqualWhatReachedVulkan) {
  Settings base = smallFrame(19, 11, 4);
  expectExact(base, "unsorted");
  Settings s = base;
  s.traceShade = TraceShade::Fused;
  expectExact(s, "trace+shade");
  s.traceShade = TraceShade::Loop;
  expectExact(s, "trace+shade loop");
  s = base;
  s.kernel = Kernel::Megakernel;
  expectExact(s, "megakernel");
  s = base;
  s.strategy = KeyStrategy::Fixed;
  s.sortPolicy = SortPolicy::Always;
  for (SortAlgorithm sort : {SortAlgorithm::Radix, SortAlgorithm::Bitonic, SortAlgorithm::Tile})
    for (Fusion fusion : {Fusion::None, Fusion::Gather}) {
      s.sort = sort;
      s.fusion = fusion;
      expectExact(s, "fixed " + toString(sort) + " fusion " + toString(fusion));
    }
  s.fusion = Fusion::Keys;
  s.sort = SortAlgorithm::Radix;
  expectExact(s, "keys in shade");
  // Past the small sort's threshold, the radix passes and OneSweep's (its fill of the look-back state is a
  // transfer, not a dispatch).
  Settings large = smallFrame(48, 43, 3);
  large.strategy = KeyStrategy::TwoPoint;
  large.sortPolicy = SortPolicy::Always;
  ASSERT_GT(large.width * large.height, uint32_t(SORT_SMALL_MAX));
  for (SortAlgorithm sort : {SortAlgorithm::Radix, SortAlgorithm::OneSweep}) {
    large.sort = sort;
    expectExact(large, "two-point " + toString(sort) + " past the small sort");
  }
  s = base;
  s.strategy = KeyStrategy::Average;
  s.sortPolicy = SortPolicy::Always;
  expectExact(s, "average, detailed", true);
}

// The unsorted wavefront: generate, each bounce's trace and shade (indirect, over the live paths),
// accumulate and tonemap; a barrier after each stage, three in setup (the frame block, the cleared counters,
// the stage's own), one between a compacting shade and its copy of the live block, one before the host
// reads. Sizes: generate's, setup's cleared append blocks and each compacting shade's append and copy.
TEST_F(CommandCountsTest, FollowTheBouncesAndStages) {
  for (uint32_t bounces : {1u, 3u})
    for (Compaction compaction : {Compaction::None, Compaction::Shade}) {
      Settings s = smallFrame(19, 11, bounces);
      s.compaction = compaction;
      const std::string what = std::to_string(bounces) + " bounces, compaction " + toString(compaction);
      const bool compacts = compaction == Compaction::Shade && bounces > 1;
      const uint32_t compactingShades = compacts ? bounces - 1 : 0;
      Issued issued;
      const FrameStats split = render(s, issued);
      EXPECT_EQ(split.commands.directDispatches, 3u) << what;
      EXPECT_EQ(split.commands.indirectDispatches, 2 * bounces) << what;
      EXPECT_EQ(split.commands.barriers, 3 + 1 + 2 * bounces + compactingShades + 2 + 1) << what;
      EXPECT_EQ(split.commands.sizeWrites, 1 + (compacts ? 1 : 0) + 2 * compactingShades) << what;
      EXPECT_EQ(stageDispatches(split, "trace"), bounces) << what;
      EXPECT_EQ(stageDispatches(split, "shade"), bounces) << what;
      EXPECT_EQ(stageDispatches(split, "generate"), 1u) << what;

      s.traceShade = TraceShade::Fused;
      const FrameStats fused = render(s, issued);
      EXPECT_EQ(fused.commands.indirectDispatches, bounces) << what << ", fused";
      EXPECT_EQ(fused.commands.barriers, split.commands.barriers - bounces) << what << ", fused";
      EXPECT_EQ(stageDispatches(fused, "trace+shade"), bounces) << what << ", fused";

      s.kernel = Kernel::Megakernel;
      const FrameStats mega = render(s, issued);
      EXPECT_EQ(mega.commands.dispatches(), 3u) << what << ", megakernel";
      EXPECT_EQ(mega.commands.barriers, 3 + 1 + 2 + 1u) << what << ", megakernel";
    }
}

// A sorted frame adds, after every bounce but the last (policy always), one keys dispatch, one sort (this
// frame is small) and, without the gather fused into the next trace, one reorder; a frame in steps counts the same commands and one round
// trip per submission.
TEST_F(CommandCountsTest, SortedBouncesAndSubmissions) {
  Settings s = smallFrame(19, 11, 4);
  s.strategy = KeyStrategy::Fixed;
  s.sortPolicy = SortPolicy::Always;
  s.fusion = Fusion::None;
  Issued issued;
  const FrameStats whole = render(s, issued);
  EXPECT_EQ(stageDispatches(whole, "keys"), 3u);
  EXPECT_EQ(stageDispatches(whole, "reorder"), 3u);
  EXPECT_EQ(stageDispatches(whole, "sort"), 3u);  // 209 paths: the small sort, one dispatch a sorted bounce

  PathTracer parts(ctx(), scene_, s, *scene_.findViewpoint("openings"));
  parts.renderFrame();
  const FrameStats* done = nullptr;
  uint32_t submissions = 0;
  while (!done) {
    ctx().submitAndWait([&](VkCommandBuffer cmd) { parts.recordSteps(cmd, 3); });
    done = parts.finishSteps(1.0);
    ++submissions;
  }
  EXPECT_GT(submissions, 1u);
  EXPECT_EQ(done->submissions, submissions);
  EXPECT_EQ(done->commands, whole.commands);
}

}  // namespace
}  // namespace raylab::test

namespace raylab::test {
namespace {

class EmptyDispatchTest : public GpuTest {};

// The empty dispatch's cost is a time the device reports: a finite, non-negative number of microseconds, and
// none for no dispatches. No bound on its size: how long a dispatch takes is the machine's speed, and on a
// shared CPU device a descheduled thread makes the longer run no longer than the shorter one (the cost then
// reads 0) or makes it many milliseconds long (CI failed once on an upper bound of 1 ms).
TEST_F(EmptyDispatchTest, IsAFiniteTimeOrNone) {
  if (!ctx().info().timestamps) GTEST_SKIP() << "the device has no timestamps";
  const std::optional<double> us = measureEmptyDispatchUs(ctx(), 32, 3);
  ASSERT_TRUE(us.has_value());
  EXPECT_TRUE(std::isfinite(*us));
  EXPECT_GE(*us, 0.0);
  EXPECT_FALSE(measureEmptyDispatchUs(ctx(), 0, 3).has_value());
}

}  // namespace
}  // namespace raylab::test
