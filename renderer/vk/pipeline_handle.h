// What every pipeline of ours owns, compute or ray tracing: the VkPipeline and its layout (push constants
// only, no descriptor sets: buffers reach the shaders as device addresses), the shader's name for messages
// and the push-constant size its SPIR-V declares. Move-only; destroys both handles.
#pragma once

#include <cstdint>
#include <string>

#include <vulkan/vulkan.h>

namespace raylab {

class VulkanContext;

class PipelineHandle {
 public:
  PipelineHandle() = default;
  // Checks `pushBytes` (callers pass sizeof(their struct)) against the block the SPIR-V of `shaderName`
  // declares and the guaranteed 128 bytes, throwing VulkanError on a mismatch, and creates the layout
  // with one push-constant range for `stages`. The owner creates the pipeline into `pipeline`.
  PipelineHandle(const VulkanContext& ctx, const std::string& shaderName, uint32_t pushBytes,
                 VkShaderStageFlags stages);
  ~PipelineHandle();
  PipelineHandle(PipelineHandle&& other) noexcept;
  PipelineHandle& operator=(PipelineHandle&& other) noexcept;
  PipelineHandle(const PipelineHandle&) = delete;
  PipelineHandle& operator=(const PipelineHandle&) = delete;

  // Throws unless `bytes` (sizeof the struct a caller pushes) is the declared block size.
  void checkPushSize(size_t bytes) const;
  // Binds the pipeline at `bindPoint` and pushes the constants (if the shader declares any).
  void bindAndPush(VkCommandBuffer cmd, VkPipelineBindPoint bindPoint, const void* push) const;

  const VulkanContext* ctx = nullptr;
  std::string name;
  VkShaderStageFlags stages = 0;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkPipeline pipeline = VK_NULL_HANDLE;
  uint32_t pushBytes = 0;

 private:
  void release();
};

// A shader module of the embedded SPIR-V `shaderName`; the caller destroys it once the pipeline exists.
VkShaderModule makeShaderModule(const VulkanContext& ctx, const std::string& shaderName);

}  // namespace raylab
