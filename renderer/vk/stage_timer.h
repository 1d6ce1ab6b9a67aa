// Named GPU timer scopes, summed by name (no hand-numbered timestamps). Stages that record commands take a
// StageTimer* and wrap each dispatch chain in begin/end; nullptr means untimed.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

#include <vulkan/vulkan.h>

#include "renderer/stages.h"
#include "renderer/vk/command_counts.h"
#include "renderer/vk/compute_pipeline.h"

namespace raylab {

class StageTimer {
 public:
  virtual ~StageTimer() = default;
  virtual void begin(VkCommandBuffer cmd, std::string_view stage) = 0;
  virtual void end(VkCommandBuffer cmd) = 0;
};

// RAII scope: ScopedStage s(timer, cmd, "trace"); the commands recorded inside it count as the stage's
// (command_counts.h), timed or not.
class ScopedStage {
 public:
  ScopedStage(StageTimer* timer, VkCommandBuffer cmd, std::string_view stage) : timer_(timer), cmd_(cmd) {
    // Every stage has a row in renderer/stages.h, where the bench, the charts and the UI read them from.
    if (!findStage(stage)) throw std::logic_error("stage '" + std::string(stage) + "' is not in renderer/stages.h");
    enterCommandStage(cmd_, stage);
    if (timer_) timer_->begin(cmd_, stage);
  }
  ~ScopedStage() {
    if (timer_) timer_->end(cmd_);
    leaveCommandStage(cmd_);
  }
  ScopedStage(const ScopedStage&) = delete;
  ScopedStage& operator=(const ScopedStage&) = delete;

 private:
  StageTimer* timer_;
  VkCommandBuffer cmd_;
};

// One step of the frame loop, like pbrt's ParallelFor by name or Falcor's profiled pass: names and times
// the dispatches `record` records, then fences them with a compute barrier so the next step sees their
// writes. recordStage(cmd, timer, "shade", [&] { shade.dispatchThreads(cmd, push, n); });
template <class Record>
void recordStage(VkCommandBuffer cmd, StageTimer* timer, std::string_view name, Record&& record) {
  ScopedStage scope(timer, cmd, name);
  record();
  computeBarrier(cmd);
}

}  // namespace raylab
