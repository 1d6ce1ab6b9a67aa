// One compute shader as a pipeline with no descriptor sets: every buffer reaches the shader as a device
// address inside its push constants. The work-group size is specialization constant RL_SPEC_GROUP_SIZE
// (local_size_x_id) so the host knows it without reflection; further {RL_SPEC_*, value} pairs select variants.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "renderer/vk/command_counts.h"
#include "renderer/vk/pipeline_handle.h"
#include "renderer/vk/spec_constants.h"

namespace raylab {

class VulkanContext;

// Whether a shader writes an indirect dispatch size (GpuFrame::live: generate, the reorder, the gathering
// trace, the compacting shade): declared where its pipeline is made, so each of its dispatches also counts
// as a size write (command_counts.h).
enum class WritesSizes : bool { No, Yes };

class ComputePipeline {
 public:
  ComputePipeline() = default;
  // `pushBytes` (callers pass sizeof(their struct)) must equal the push-constant block size the SPIR-V
  // declares, or the constructor throws; every dispatch checks sizeof(Push) against it again.
  ComputePipeline(const VulkanContext& ctx, const std::string& shaderName, uint32_t pushBytes,
                  uint32_t groupSize = 64, const SpecConstants& variant = {}, WritesSizes writesSizes = WritesSizes::No);

  uint32_t groupSize() const { return groupSize_; }
  const std::string& name() const { return handle_.name; }

  // Binds, pushes constants and dispatches enough groups to cover `threads` threads (none if zero), in rows
  // (dispatch_size.h): the shader finds its index with dispatch_index.glsl's flatInvocationIndex().
  void dispatchThreads(VkCommandBuffer cmd, const void* push, uint64_t threads) const;
  // Binds, pushes constants and dispatches exactly `groups` work groups in x, at most the device's limit
  // (shaders that index by gl_WorkGroupID.x; the sorts split larger counts themselves).
  void dispatchGroups(VkCommandBuffer cmd, const void* push, uint32_t groups) const;

  // Binds, pushes constants and dispatches the group counts stored at `offset` in `args` (x, y, z uints).
  template <class Push>
  void dispatchIndirect(VkCommandBuffer cmd, const Push& push, VkBuffer args, VkDeviceSize offset) const {
    handle_.checkPushSize(sizeof(Push));
    handle_.bindAndPush(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, &push);
    vkCmdDispatchIndirect(cmd, args, offset);
    counted(cmd, CommandKind::IndirectDispatch);
  }
  template <class Push>
  void dispatchThreads(VkCommandBuffer cmd, const Push& push, uint64_t threads) const {
    handle_.checkPushSize(sizeof(Push));
    dispatchThreads(cmd, static_cast<const void*>(&push), threads);
  }
  template <class Push>
  void dispatchGroups(VkCommandBuffer cmd, const Push& push, uint32_t groups) const {
    handle_.checkPushSize(sizeof(Push));
    dispatchGroups(cmd, static_cast<const void*>(&push), groups);
  }

 private:
  // Counts one dispatch of `kind` just recorded into `cmd`, and a size write where the shader writes sizes.
  void counted(VkCommandBuffer cmd, CommandKind kind) const;

  PipelineHandle handle_;
  uint32_t groupSize_ = 0;
  WritesSizes writesSizes_ = WritesSizes::No;
};

// Makes all earlier shader and transfer writes visible to later shader and transfer reads and writes; the
// ray-tracing shader stage is on both sides once a context enabled ray tracing (setRayTracingBarriers),
// so the rt tracer's stages are fenced like compute ones.
void computeBarrier(VkCommandBuffer cmd);
// Makes the frame's shader and transfer writes visible to the host (after its last copy to a readback).
void hostReadBarrier(VkCommandBuffer cmd);
void setRayTracingBarriers(bool on);

}  // namespace raylab
