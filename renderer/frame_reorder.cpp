#include "renderer/frame_reorder.h"

#include "renderer/path_buffers.h"
#include "renderer/stage_timer.h"
#include "renderer/vk_context.h"

namespace raylab {

struct ReorderPush {
  VkDeviceAddress frame;
  VkDeviceAddress sortedIndices;
  uint32_t stateSet;
  uint32_t count;
};

FrameReorder::FrameReorder(const VulkanContext& ctx, const Scene&, const Settings& settings, glm::vec3)
    : ctx_(ctx), settings_(settings), gather_(ctx, "reorder", sizeof(ReorderPush), RL_PATH_GROUP_SIZE) {}

FrameReorder::~FrameReorder() = default;

void FrameReorder::configure(const Settings& settings, glm::vec3, bool) { settings_ = settings; }

void FrameReorder::resize(uint32_t) {}

void FrameReorder::recordLearn(VkCommandBuffer, VkDeviceAddress, uint32_t, uint32_t, uint32_t, StageTimer*) {}

uint32_t FrameReorder::recordReorder(VkCommandBuffer cmd, VkDeviceAddress frame, uint32_t stateSet, uint32_t,
                                     uint32_t count, const PathBuffers& buffers, StageTimer* timer) {
  ScopedStage s(timer, cmd, "reorder");
  ReorderPush push{frame, buffers.values.address(), stateSet, count};
  gather_.dispatchThreads(cmd, push, count);
  computeBarrier(cmd);
  return 1u - stateSet;
}

void FrameReorder::finishFrame(FrameStats&, bool) {}

}  // namespace raylab
