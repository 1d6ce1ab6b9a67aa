#include "renderer/vk/rt_pipeline.h"

#include <cstring>

#include "renderer/vk/align_up.h"
#include "renderer/vk/command_counts.h"
#include "renderer/vk/vk_check.h"
#include "renderer/vk/vk_context.h"

namespace raylab {
namespace {


// The context, once it is known to have ray-tracing pipelines (a clear message, not a failed create).
const VulkanContext& requireRayTracing(const VulkanContext& ctx, const std::string& raygenName) {
  if (!ctx.info().rayTracing) throw VulkanError(raygenName + ": the device has no ray-tracing pipelines");
  return ctx;
}

}  // namespace

RtPipeline::RtPipeline(const VulkanContext& ctx, const std::string& raygenName, uint32_t pushBytes,
                       const SpecConstants& constants)
    : handle_(requireRayTracing(ctx, raygenName), raygenName, pushBytes, VK_SHADER_STAGE_RAYGEN_BIT_KHR) {
  const char* names[] = {raygenName.c_str(), "rt_miss", "rt_shadow_miss", "rt_closest_hit"};
  const VkShaderStageFlagBits kinds[] = {VK_SHADER_STAGE_RAYGEN_BIT_KHR, VK_SHADER_STAGE_MISS_BIT_KHR,
                                         VK_SHADER_STAGE_MISS_BIT_KHR, VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR};
  const Specialization spec(constants, raygenName);
  VkPipelineShaderStageCreateInfo stages[4];
  VkRayTracingShaderGroupCreateInfoKHR groups[4];
  for (uint32_t i = 0; i < 4; ++i) {
    stages[i] = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    stages[i].stage = kinds[i];
    stages[i].module = makeShaderModule(ctx, names[i]);
    stages[i].pName = "main";
    if (i == 0) stages[i].pSpecializationInfo = spec.info();
    groups[i] = {VK_STRUCTURE_TYPE_RAY_TRACING_SHADER_GROUP_CREATE_INFO_KHR};
    groups[i].type = i < 3 ? VK_RAY_TRACING_SHADER_GROUP_TYPE_GENERAL_KHR
                           : VK_RAY_TRACING_SHADER_GROUP_TYPE_TRIANGLES_HIT_GROUP_KHR;
    groups[i].generalShader = i < 3 ? i : VK_SHADER_UNUSED_KHR;
    groups[i].closestHitShader = i == 3 ? i : VK_SHADER_UNUSED_KHR;
    groups[i].anyHitShader = VK_SHADER_UNUSED_KHR;
    groups[i].intersectionShader = VK_SHADER_UNUSED_KHR;
  }
  VkRayTracingPipelineCreateInfoKHR pipelineInfo{VK_STRUCTURE_TYPE_RAY_TRACING_PIPELINE_CREATE_INFO_KHR};
  pipelineInfo.stageCount = 4;
  pipelineInfo.pStages = stages;
  pipelineInfo.groupCount = 4;
  pipelineInfo.pGroups = groups;
  pipelineInfo.maxPipelineRayRecursionDepth = 1;  // only ray-generation shaders trace
  pipelineInfo.layout = handle_.layout;
  VkResult r = ctx.rt().createRayTracingPipelines(ctx.device(), VK_NULL_HANDLE, VK_NULL_HANDLE, 1, &pipelineInfo,
                                                  nullptr, &handle_.pipeline);
  for (const auto& s : stages) vkDestroyShaderModule(ctx.device(), s.module, nullptr);
  if (r != VK_SUCCESS) throw VulkanError("creating ray-tracing pipeline " + raygenName + " failed: " + vkResultName(r));
  buildShaderTable(ctx);
}

void RtPipeline::buildShaderTable(const VulkanContext& ctx) {
  const DeviceInfo& info = ctx.info();
  const uint32_t handleSize = info.shaderGroupHandleSize;
  const VkDeviceSize stride = alignUp(handleSize, info.shaderGroupHandleAlignment);
  const VkDeviceSize base = std::max<VkDeviceSize>(info.shaderGroupBaseAlignment, 1);
  const VkDeviceSize raygenOffset = 0, missOffset = alignUp(stride, base), hitOffset = alignUp(missOffset + 2 * stride, base);
  const VkDeviceSize tableBytes = hitOffset + stride;
  std::vector<uint8_t> handles(4 * handleSize);
  VK_CHECK(ctx.rt().getRayTracingShaderGroupHandles(ctx.device(), handle_.pipeline, 0, 4, handles.size(), handles.data()));
  std::vector<uint8_t> table(tableBytes + base, 0);
  // The buffer's address need not be base-aligned: the table starts at the first aligned byte in it.
  table_ = GpuBuffer(ctx, table.size(), MemoryKind::DeviceLocal, VK_BUFFER_USAGE_SHADER_BINDING_TABLE_BIT_KHR);
  const VkDeviceSize start = alignUp(table_.address(), base) - table_.address();
  std::memcpy(&table[start + raygenOffset], &handles[0], handleSize);
  std::memcpy(&table[start + missOffset], &handles[handleSize], handleSize);
  std::memcpy(&table[start + missOffset + stride], &handles[2 * handleSize], handleSize);
  std::memcpy(&table[start + hitOffset], &handles[3 * handleSize], handleSize);
  table_.uploadVector(table);
  const VkDeviceAddress at = table_.address() + start;
  raygen_ = {at + raygenOffset, stride, stride};
  miss_ = {at + missOffset, stride, 2 * stride};
  hit_ = {at + hitOffset, stride, stride};
}

void RtPipeline::traceRays(VkCommandBuffer cmd, const void* push, uint32_t width) const {
  if (width == 0) return;
  if (width > handle_.ctx->info().maxRayDispatchInvocationCount)
    throw VulkanError(handle_.name + ": " + std::to_string(width) + " rays exceed the device's launch limit");
  handle_.bindAndPush(cmd, VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR, push);
  handle_.ctx->rt().cmdTraceRays(cmd, &raygen_, &miss_, &hit_, &callable_, width, 1, 1);
  countCommand(cmd, CommandKind::Dispatch);  // a launch of its own, as a compute dispatch is
}

}  // namespace raylab
