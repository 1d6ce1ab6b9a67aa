#include "renderer/vk/pipeline_handle.h"

#include <utility>

#include "renderer/vk/shader_table.h"
#include "renderer/vk/spirv_reflect.h"
#include "renderer/vk/vk_check.h"
#include "renderer/vk/vk_context.h"

namespace raylab {

PipelineHandle::PipelineHandle(const VulkanContext& context, const std::string& shaderName, uint32_t bytes,
                               VkShaderStageFlags shaderStages)
    : ctx(&context), name(shaderName), stages(shaderStages), pushBytes(bytes) {
  if (bytes > 128) throw VulkanError(shaderName + ": push constants over the guaranteed 128 bytes");
  if (uint32_t declared = spirvPushConstantBytes(shaderSpirv(shaderName)); declared != bytes)
    throw VulkanError(shaderName + ": the shader's push constants are " + std::to_string(declared) +
                      " bytes, the host's struct " + std::to_string(bytes));
  VkPushConstantRange range{shaderStages, 0, bytes};
  VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layoutInfo.pushConstantRangeCount = bytes ? 1 : 0;
  layoutInfo.pPushConstantRanges = &range;
  VK_CHECK(vkCreatePipelineLayout(context.device(), &layoutInfo, nullptr, &layout));
}

PipelineHandle::~PipelineHandle() { release(); }

PipelineHandle::PipelineHandle(PipelineHandle&& o) noexcept { *this = std::move(o); }

PipelineHandle& PipelineHandle::operator=(PipelineHandle&& o) noexcept {
  if (this != &o) {
    release();
    ctx = std::exchange(o.ctx, nullptr);
    name = std::move(o.name);
    stages = o.stages;
    layout = std::exchange(o.layout, VK_NULL_HANDLE);
    pipeline = std::exchange(o.pipeline, VK_NULL_HANDLE);
    pushBytes = o.pushBytes;
  }
  return *this;
}

void PipelineHandle::release() {
  if (!ctx) return;
  if (pipeline) vkDestroyPipeline(ctx->device(), pipeline, nullptr);
  if (layout) vkDestroyPipelineLayout(ctx->device(), layout, nullptr);
  pipeline = VK_NULL_HANDLE;
  layout = VK_NULL_HANDLE;
}

void PipelineHandle::checkPushSize(size_t bytes) const {
  if (bytes != pushBytes)
    throw VulkanError(name + ": push constants of " + std::to_string(bytes) + " bytes, pipeline declares " +
                      std::to_string(pushBytes));
}

void PipelineHandle::bindAndPush(VkCommandBuffer cmd, VkPipelineBindPoint bindPoint, const void* push) const {
  vkCmdBindPipeline(cmd, bindPoint, pipeline);
  if (pushBytes) vkCmdPushConstants(cmd, layout, stages, 0, pushBytes, push);
}

VkShaderModule makeShaderModule(const VulkanContext& ctx, const std::string& shaderName) {
  std::span<const uint32_t> code = shaderSpirv(shaderName);
  VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  info.codeSize = code.size() * sizeof(uint32_t);
  info.pCode = code.data();
  VkShaderModule module;
  VK_CHECK(vkCreateShaderModule(ctx.device(), &info, nullptr, &module));
  return module;
}

}  // namespace raylab
