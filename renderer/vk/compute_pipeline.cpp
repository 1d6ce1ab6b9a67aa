#include "renderer/vk/compute_pipeline.h"

#include <atomic>
#include <utility>

#include "renderer/vk/shader_table.h"
#include "renderer/vk/spirv_reflect.h"
#include "renderer/vk/vk_check.h"
#include "renderer/vk/vk_context.h"

namespace raylab {

ComputePipeline::ComputePipeline(const VulkanContext& ctx, const std::string& shaderName, uint32_t pushBytes,
                                 uint32_t groupSize, const std::vector<uint32_t>& extraConstants)
    : ctx_(&ctx), name_(shaderName), pushBytes_(pushBytes), groupSize_(groupSize) {
  if (pushBytes > 128) throw VulkanError(shaderName + ": push constants over the guaranteed 128 bytes");
  std::span<const uint32_t> code = shaderSpirv(shaderName);
  if (uint32_t declared = spirvPushConstantBytes(code); declared != pushBytes)
    throw VulkanError(shaderName + ": the shader's push constants are " + std::to_string(declared) +
                      " bytes, the host's struct " + std::to_string(pushBytes));
  VkShaderModuleCreateInfo moduleInfo{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  moduleInfo.codeSize = code.size() * sizeof(uint32_t);
  moduleInfo.pCode = code.data();
  VkShaderModule module;
  VK_CHECK(vkCreateShaderModule(ctx.device(), &moduleInfo, nullptr, &module));

  VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, pushBytes};
  VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layoutInfo.pushConstantRangeCount = pushBytes ? 1 : 0;
  layoutInfo.pPushConstantRanges = &range;
  VK_CHECK(vkCreatePipelineLayout(ctx.device(), &layoutInfo, nullptr, &layout_));

  std::vector<uint32_t> constants{groupSize};
  constants.insert(constants.end(), extraConstants.begin(), extraConstants.end());
  std::vector<VkSpecializationMapEntry> entries;
  for (uint32_t i = 0; i < constants.size(); ++i)
    entries.push_back({i, static_cast<uint32_t>(i * sizeof(uint32_t)), sizeof(uint32_t)});
  VkSpecializationInfo spec{static_cast<uint32_t>(entries.size()), entries.data(),
                            constants.size() * sizeof(uint32_t), constants.data()};

  VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.module = module;
  info.stage.pName = "main";
  info.stage.pSpecializationInfo = &spec;
  info.layout = layout_;
  VkResult r = vkCreateComputePipelines(ctx.device(), VK_NULL_HANDLE, 1, &info, nullptr, &pipeline_);
  vkDestroyShaderModule(ctx.device(), module, nullptr);
  if (r != VK_SUCCESS) throw VulkanError("creating pipeline " + shaderName + " failed: " + vkResultName(r));
}

ComputePipeline::~ComputePipeline() { release(); }

ComputePipeline::ComputePipeline(ComputePipeline&& o) noexcept { *this = std::move(o); }

ComputePipeline& ComputePipeline::operator=(ComputePipeline&& o) noexcept {
  if (this != &o) {
    release();
    ctx_ = std::exchange(o.ctx_, nullptr);
    name_ = std::move(o.name_);
    layout_ = std::exchange(o.layout_, VK_NULL_HANDLE);
    pipeline_ = std::exchange(o.pipeline_, VK_NULL_HANDLE);
    pushBytes_ = o.pushBytes_;
    groupSize_ = o.groupSize_;
  }
  return *this;
}

void ComputePipeline::release() {
  if (!ctx_) return;
  if (pipeline_) vkDestroyPipeline(ctx_->device(), pipeline_, nullptr);
  if (layout_) vkDestroyPipelineLayout(ctx_->device(), layout_, nullptr);
  pipeline_ = VK_NULL_HANDLE;
  layout_ = VK_NULL_HANDLE;
}

void ComputePipeline::checkPushSize(size_t bytes) const {
  if (bytes != pushBytes_)
    throw VulkanError(name_ + ": push constants of " + std::to_string(bytes) + " bytes, pipeline declares " +
                      std::to_string(pushBytes_));
}

void ComputePipeline::dispatchGroups(VkCommandBuffer cmd, const void* push, uint32_t groups) const {
  if (groups == 0) return;
  if (groups > ctx_->info().maxGroupCountX)
    throw VulkanError(name_ + ": " + std::to_string(groups) + " work groups exceed the device limit");
  bindAndPush(cmd, push);
  vkCmdDispatch(cmd, groups, 1, 1);
}

void ComputePipeline::bindAndPush(VkCommandBuffer cmd, const void* push) const {
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
  if (pushBytes_) vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, pushBytes_, push);
}

void ComputePipeline::dispatchThreads(VkCommandBuffer cmd, const void* push, uint64_t threads) const {
  dispatchGroups(cmd, push, static_cast<uint32_t>((threads + groupSize_ - 1) / groupSize_));
}

namespace {
// Every context of a process picks the same device features, so one flag serves them all.
std::atomic<VkPipelineStageFlags> gExtraShaderStages{0};
}  // namespace

void setRayTracingBarriers(bool on) {
  gExtraShaderStages = on ? VkPipelineStageFlags(VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR) : 0;
}

void computeBarrier(VkCommandBuffer cmd) {
  // Indirect dispatch sizes written by a shader (GpuFrame::live) are read by the DRAW_INDIRECT stage, so
  // it is part of the destination: without it a GPU may launch a stage with a stale group count.
  VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_READ_BIT |
                          VK_ACCESS_TRANSFER_WRITE_BIT | VK_ACCESS_INDIRECT_COMMAND_READ_BIT;
  const VkPipelineStageFlags extra = gExtraShaderStages.load();
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT | extra,
                       VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT |
                           VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT | extra,
                       0, 1, &barrier, 0, nullptr, 0, nullptr);
}

}  // namespace raylab
