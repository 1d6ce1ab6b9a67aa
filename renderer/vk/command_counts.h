// What a frame costs before any of its work: how many dispatches, barriers and indirect-size writes its
// command buffers hold (issue 36). Every such command is recorded in renderer/vk (ComputePipeline's
// dispatches, RtPipeline::traceRays, computeBarrier, hostReadBarrier, the size transfers of size_writes.h),
// and each of those calls countCommand: the one place a command is counted is the one place it is recorded.
// A recorder that wants counts opens a CountCommands scope over its command buffer; commands recorded into
// a buffer without a scope (uploads, BVH builds) are not counted. ScopedStage (stage_timer.h) names the
// stage the commands belong to, so the counts come per stage as well as in total.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <vulkan/vulkan.h>

#include "renderer/frame_commands.h"

namespace raylab {

// The counts of one recorder, per stage in the order the stages were first recorded.
class CommandTally {
 public:
  void add(std::string_view stage, CommandKind kind);
  void clear() { stages_.clear(); }
  const std::vector<StageCommands>& stages() const { return stages_; }
  CommandCounts total() const;

 private:
  std::vector<StageCommands> stages_;
};

// While alive, commands recorded into `cmd` on this thread count into `tally`. Scopes nest (the innermost
// scope of a buffer counts); each thread records its own buffers, so the registry is per thread.
class CountCommands {
 public:
  CountCommands(VkCommandBuffer cmd, CommandTally& tally);
  ~CountCommands();
  CountCommands(const CountCommands&) = delete;
  CountCommands& operator=(const CountCommands&) = delete;
};

// Called where each kind of command is recorded (renderer/vk only).
void countCommand(VkCommandBuffer cmd, CommandKind kind);
// The stage the next commands of `cmd` belong to, entered and left by ScopedStage; stages nest.
void enterCommandStage(VkCommandBuffer cmd, std::string_view stage);
void leaveCommandStage(VkCommandBuffer cmd);

}  // namespace raylab
