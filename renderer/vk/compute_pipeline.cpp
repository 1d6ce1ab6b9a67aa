#include "renderer/vk/compute_pipeline.h"

#include <atomic>

#include "renderer/vk/dispatch_size.h"
#include "renderer/vk/pipeline_statistics.h"
#include "renderer/vk/vk_check.h"
#include "renderer/vk/vk_context.h"

namespace raylab {

ComputePipeline::ComputePipeline(const VulkanContext& ctx, const std::string& shaderName, uint32_t pushBytes,
                                 uint32_t groupSize, const SpecConstants& variant, WritesSizes writesSizes)
    : handle_(ctx, shaderName, pushBytes, VK_SHADER_STAGE_COMPUTE_BIT), groupSize_(groupSize), writesSizes_(writesSizes) {
  SpecConstants constants{{RL_SPEC_GROUP_SIZE, groupSize}};
  constants.insert(constants.end(), variant.begin(), variant.end());
  const Specialization spec(constants, shaderName);

  VkShaderModule module = makeShaderModule(ctx, shaderName);
  VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.module = module;
  info.stage.pName = "main";
  info.stage.pSpecializationInfo = spec.info();
  info.layout = handle_.layout;
  if (ctx.info().shaderStatistics) info.flags |= VK_PIPELINE_CREATE_CAPTURE_STATISTICS_BIT_KHR;
  VkResult r = vkCreateComputePipelines(ctx.device(), VK_NULL_HANDLE, 1, &info, nullptr, &handle_.pipeline);
  vkDestroyShaderModule(ctx.device(), module, nullptr);
  if (r != VK_SUCCESS) throw VulkanError("creating pipeline " + shaderName + " failed: " + vkResultName(r));
  if (ctx.info().shaderStatistics) {
    std::string variantName = shaderName;
    for (const auto& [id, value] : constants) variantName += " " + std::to_string(id) + "=" + std::to_string(value);
    printShaderStatistics(ctx.device(), handle_.pipeline, variantName);
  }
}

void ComputePipeline::dispatchGroups(VkCommandBuffer cmd, const void* push, uint32_t groups) const {
  if (groups == 0) return;
  if (groups > handle_.ctx->info().maxGroupCountX)
    throw VulkanError(handle_.name + ": " + std::to_string(groups) + " work groups exceed the device limit");
  handle_.bindAndPush(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, push);
  vkCmdDispatch(cmd, groups, 1, 1);
  counted(cmd, CommandKind::Dispatch);
}

void ComputePipeline::dispatchThreads(VkCommandBuffer cmd, const void* push, uint64_t threads) const {
  const DeviceInfo& device = handle_.ctx->info();
  const DispatchSize size = dispatchSizeFor(threads, groupSize_, device.dispatchRowGroups, device.maxGroupCountY);
  if (size.x == 0) return;
  handle_.bindAndPush(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, push);
  vkCmdDispatch(cmd, size.x, size.y, 1);
  counted(cmd, CommandKind::Dispatch);
}

void ComputePipeline::counted(VkCommandBuffer cmd, CommandKind kind) const {
  countCommand(cmd, kind);
  if (writesSizes_ == WritesSizes::Yes) countCommand(cmd, CommandKind::SizeWrite);
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
  countCommand(cmd, CommandKind::Barrier);
}

void hostReadBarrier(VkCommandBuffer cmd) {
  VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  toHost.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
  toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                       VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0, nullptr, 0, nullptr);
  countCommand(cmd, CommandKind::Barrier);
}

}  // namespace raylab
