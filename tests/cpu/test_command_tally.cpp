// The command counter's bookkeeping without a device (renderer/vk/command_counts.h): commands count only into
// the scope of their own command buffer, under the innermost stage entered in it, and nowhere without a scope.
#include <gtest/gtest.h>

#include <cstdint>

#include "renderer/vk/command_counts.h"

namespace raylab {
namespace {

VkCommandBuffer fakeBuffer(uintptr_t n) { return reinterpret_cast<VkCommandBuffer>(n); }

TEST(CommandTally, CountsPerBufferAndInnermostStage) {
  const VkCommandBuffer a = fakeBuffer(16), b = fakeBuffer(32);
  countCommand(a, CommandKind::Dispatch);  // no scope: not counted anywhere
  CommandTally tally, other;
  {
    CountCommands counting(a, tally);
    countCommand(a, CommandKind::Barrier);  // outside any stage: stage ""
    enterCommandStage(a, "sort");
    countCommand(a, CommandKind::Dispatch);
    countCommand(b, CommandKind::Dispatch);  // another buffer, no scope of its own
    enterCommandStage(a, "counters");
    countCommand(a, CommandKind::IndirectDispatch);
    {
      CountCommands inner(a, other);  // the innermost scope of a buffer counts
      countCommand(a, CommandKind::SizeWrite);
    }
    leaveCommandStage(a);
    countCommand(a, CommandKind::Barrier);
    leaveCommandStage(a);
  }
  countCommand(a, CommandKind::Dispatch);  // the scope ended
  ASSERT_EQ(tally.stages().size(), 3u);
  EXPECT_EQ(tally.stages()[0].stage, "");
  EXPECT_EQ(tally.stages()[0].counts, (CommandCounts{0, 0, 1, 0}));
  EXPECT_EQ(tally.stages()[1].stage, "sort");
  EXPECT_EQ(tally.stages()[1].counts, (CommandCounts{1, 0, 1, 0}));
  EXPECT_EQ(tally.stages()[2].stage, "counters");
  EXPECT_EQ(tally.stages()[2].counts, (CommandCounts{0, 1, 0, 0}));
  EXPECT_EQ(tally.total(), (CommandCounts{1, 1, 2, 0}));
  EXPECT_EQ(tally.total().dispatches(), 2u);
  EXPECT_EQ(other.total(), (CommandCounts{0, 0, 0, 1}));
  tally.clear();
  EXPECT_TRUE(tally.stages().empty());
}

}  // namespace
}  // namespace raylab
