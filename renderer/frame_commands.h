// The commands a frame's recording issued, as plain data for FrameStats (renderer/vk/command_counts.h
// counts them where they are recorded).
#pragma once

#include <cstdint>
#include <string>

namespace raylab {

enum class CommandKind {
  Dispatch,          // vkCmdDispatch, or one trace-rays launch
  IndirectDispatch,  // vkCmdDispatchIndirect: its size comes from a buffer the GPU wrote
  Barrier,           // vkCmdPipelineBarrier
  SizeWrite,         // a dispatch or transfer that writes an indirect dispatch size (GpuFrame::live)
};

struct CommandCounts {
  uint32_t directDispatches = 0;
  uint32_t indirectDispatches = 0;
  uint32_t barriers = 0;
  uint32_t sizeWrites = 0;

  uint32_t dispatches() const { return directDispatches + indirectDispatches; }
  void add(CommandKind kind);
  CommandCounts& operator+=(const CommandCounts& o);
  bool operator==(const CommandCounts&) const = default;
};

// The commands of one stage (renderer/stages.h; "" for commands outside any stage), summed over bounces.
struct StageCommands {
  std::string stage;
  CommandCounts counts;
};

}  // namespace raylab
