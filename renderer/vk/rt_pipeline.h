// One ray-generation shader as a VK_KHR_ray_tracing_pipeline pipeline with its shader binding table, and
// no descriptor sets (as ComputePipeline: buffers and the TLAS reach the shaders as device addresses).
// Every rt pipeline has the same miss and hit shaders, in the order rt_common.glsl names them:
//   miss 0 rt_miss (closest-hit rays), miss 1 rt_shadow_miss (shadow rays), hit group 0 rt_closest_hit.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <vulkan/vulkan.h>

#include "renderer/vk/gpu_buffer.h"
#include "renderer/vk/pipeline_handle.h"
#include "renderer/vk/spec_constants.h"

namespace raylab {

class VulkanContext;

class RtPipeline {
 public:
  RtPipeline() = default;
  // `pushBytes` must equal the ray-generation shader's push-constant block (checked against the SPIR-V);
  // `constants` are {RL_SPEC_*, value} specialization constants of the ray-generation shader.
  RtPipeline(const VulkanContext& ctx, const std::string& raygenName, uint32_t pushBytes,
             const SpecConstants& constants = {});

  // Binds, pushes constants and launches `width` x 1 x 1 ray-generation invocations (none if zero).
  template <class Push>
  void traceRays(VkCommandBuffer cmd, const Push& push, uint32_t width) const {
    handle_.checkPushSize(sizeof(Push));
    traceRays(cmd, static_cast<const void*>(&push), width);
  }

 private:
  void traceRays(VkCommandBuffer cmd, const void* push, uint32_t width) const;
  // Shader binding table: raygen | miss, shadow miss | hit, each region at a base-aligned offset.
  void buildShaderTable(const VulkanContext& ctx);

  PipelineHandle handle_;
  GpuBuffer table_;
  VkStridedDeviceAddressRegionKHR raygen_{}, miss_{}, hit_{}, callable_{};
};

}  // namespace raylab
