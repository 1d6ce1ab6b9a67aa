#include "renderer/vk/acceleration_structure.h"

#include <chrono>
#include <cstring>
#include <functional>

#include "renderer/vk/align_up.h"
#include "renderer/vk/vk_check.h"
#include "renderer/vk/vk_context.h"

namespace raylab {
namespace {

constexpr VkBufferUsageFlags kBuildInput = VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR;
constexpr VkBufferUsageFlags kStorage = VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_STORAGE_BIT_KHR;


// Sizes, storage and scratch, then one build on the queue (and `afterBuild`, fenced behind it); returns the
// structure, whose memory is `storage`.
VkAccelerationStructureKHR build(const VulkanContext& ctx, VkAccelerationStructureBuildGeometryInfoKHR info,
                                 uint32_t primitives, GpuBuffer& storage,
                                 const std::function<void(VkCommandBuffer, VkAccelerationStructureKHR)>& afterBuild) {
  VkAccelerationStructureBuildSizesInfoKHR sizes{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR};
  ctx.rt().getAccelerationStructureBuildSizes(ctx.device(), VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR, &info,
                                              &primitives, &sizes);
  storage = GpuBuffer(ctx, sizes.accelerationStructureSize, MemoryKind::DeviceLocal, kStorage);
  VkAccelerationStructureCreateInfoKHR create{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_CREATE_INFO_KHR};
  create.buffer = storage.handle();
  create.size = sizes.accelerationStructureSize;
  create.type = info.type;
  VkAccelerationStructureKHR as;
  VK_CHECK(ctx.rt().createAccelerationStructure(ctx.device(), &create, nullptr, &as));
  const VkDeviceSize align = std::max<VkDeviceSize>(ctx.info().minAccelerationStructureScratchOffsetAlignment, 1);
  GpuBuffer scratch(ctx, sizes.buildScratchSize + align);
  info.dstAccelerationStructure = as;
  info.scratchData.deviceAddress = alignUp(scratch.address(), align);
  VkAccelerationStructureBuildRangeInfoKHR range{primitives, 0, 0, 0};
  const VkAccelerationStructureBuildRangeInfoKHR* ranges = &range;
  ctx.submitAndWait([&](VkCommandBuffer cmd) {
    ctx.rt().cmdBuildAccelerationStructures(cmd, 1, &info, &ranges);
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR;
    barrier.dstAccessMask = VK_ACCESS_ACCELERATION_STRUCTURE_READ_BIT_KHR;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
                         VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR, 0, 1, &barrier, 0, nullptr, 0, nullptr);
    if (afterBuild) afterBuild(cmd, as);
  });
  return as;
}

VkDeviceAddress addressOf(const VulkanContext& ctx, VkAccelerationStructureKHR as) {
  VkAccelerationStructureDeviceAddressInfoKHR info{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_DEVICE_ADDRESS_INFO_KHR};
  info.accelerationStructure = as;
  return ctx.rt().getAccelerationStructureDeviceAddress(ctx.device(), &info);
}

}  // namespace

AccelerationStructures::AccelerationStructures(const VulkanContext& ctx, const std::vector<glm::vec3>& vertices)
    : ctx_(ctx) {
  if (!ctx.info().rayTracing) throw VulkanError("acceleration structures need " + ctx.info().rayTracingMissing);
  auto start = std::chrono::steady_clock::now();
  const uint32_t triangles = static_cast<uint32_t>(vertices.size() / 3);
  GpuBuffer vertexBuffer(ctx, vertices.size() * sizeof(glm::vec3), MemoryKind::DeviceLocal, kBuildInput);
  if (!vertices.empty()) vertexBuffer.uploadVector(vertices);

  // Bottom level: the triangles, opaque (no any-hit shader runs), built for fast tracing, then compacted.
  VkAccelerationStructureGeometryKHR geometry{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
  geometry.geometryType = VK_GEOMETRY_TYPE_TRIANGLES_KHR;
  geometry.flags = VK_GEOMETRY_OPAQUE_BIT_KHR;
  auto& tri = geometry.geometry.triangles;
  tri = {VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_TRIANGLES_DATA_KHR};
  tri.vertexFormat = VK_FORMAT_R32G32B32_SFLOAT;
  tri.vertexData.deviceAddress = vertexBuffer.address();
  tri.vertexStride = sizeof(glm::vec3);
  tri.maxVertex = vertices.empty() ? 0 : static_cast<uint32_t>(vertices.size() - 1);
  tri.indexType = VK_INDEX_TYPE_NONE_KHR;
  VkAccelerationStructureBuildGeometryInfoKHR blasInfo{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR};
  blasInfo.type = VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR;
  blasInfo.flags = VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR |
                   VK_BUILD_ACCELERATION_STRUCTURE_ALLOW_COMPACTION_BIT_KHR;
  blasInfo.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
  blasInfo.geometryCount = 1;
  blasInfo.pGeometries = &geometry;

  VkQueryPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  poolInfo.queryType = VK_QUERY_TYPE_ACCELERATION_STRUCTURE_COMPACTED_SIZE_KHR;
  poolInfo.queryCount = 1;
  VkQueryPool pool;
  VK_CHECK(vkCreateQueryPool(ctx.device(), &poolInfo, nullptr, &pool));
  GpuBuffer uncompacted;
  VkAccelerationStructureKHR full = build(ctx, blasInfo, triangles, uncompacted, [&](VkCommandBuffer cmd, VkAccelerationStructureKHR built) {
    vkCmdResetQueryPool(cmd, pool, 0, 1);
    ctx.rt().cmdWriteAccelerationStructuresProperties(cmd, 1, &built,
                                                      VK_QUERY_TYPE_ACCELERATION_STRUCTURE_COMPACTED_SIZE_KHR, pool, 0);
  });
  VkDeviceSize compacted = 0;
  VkResult r = vkGetQueryPoolResults(ctx.device(), pool, 0, 1, sizeof(compacted), &compacted, sizeof(compacted),
                                     VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT);
  vkDestroyQueryPool(ctx.device(), pool, nullptr);
  blasBytesUncompacted_ = uncompacted.size();
  if (r == VK_SUCCESS && compacted > 0 && compacted < uncompacted.size()) {
    blasBuffer_ = GpuBuffer(ctx, compacted, MemoryKind::DeviceLocal, kStorage);
    VkAccelerationStructureCreateInfoKHR create{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_CREATE_INFO_KHR};
    create.buffer = blasBuffer_.handle();
    create.size = compacted;
    create.type = VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR;
    VK_CHECK(ctx.rt().createAccelerationStructure(ctx.device(), &create, nullptr, &blas_));
    ctx.submitAndWait([&](VkCommandBuffer cmd) {
      VkCopyAccelerationStructureInfoKHR copy{VK_STRUCTURE_TYPE_COPY_ACCELERATION_STRUCTURE_INFO_KHR};
      copy.src = full;
      copy.dst = blas_;
      copy.mode = VK_COPY_ACCELERATION_STRUCTURE_MODE_COMPACT_KHR;
      ctx.rt().cmdCopyAccelerationStructure(cmd, &copy);
    });
    ctx.rt().destroyAccelerationStructure(ctx.device(), full, nullptr);
  } else {
    blas_ = full;
    blasBuffer_ = std::move(uncompacted);
  }

  // Top level: one instance of the bottom level.
  VkAccelerationStructureInstanceKHR instance{};
  instance.transform.matrix[0][0] = instance.transform.matrix[1][1] = instance.transform.matrix[2][2] = 1.0f;
  instance.mask = 0xFF;
  instance.flags = VK_GEOMETRY_INSTANCE_TRIANGLE_FACING_CULL_DISABLE_BIT_KHR;
  instance.accelerationStructureReference = addressOf(ctx, blas_);
  GpuBuffer instances(ctx, sizeof(instance), MemoryKind::DeviceLocal, kBuildInput);
  instances.upload(&instance, sizeof(instance));
  VkAccelerationStructureGeometryKHR top{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
  top.geometryType = VK_GEOMETRY_TYPE_INSTANCES_KHR;
  top.flags = VK_GEOMETRY_OPAQUE_BIT_KHR;
  top.geometry.instances = {VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_INSTANCES_DATA_KHR};
  top.geometry.instances.data.deviceAddress = instances.address();
  VkAccelerationStructureBuildGeometryInfoKHR tlasInfo{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR};
  tlasInfo.type = VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR;
  tlasInfo.flags = VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR;
  tlasInfo.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
  tlasInfo.geometryCount = 1;
  tlasInfo.pGeometries = &top;
  tlas_ = build(ctx, tlasInfo, 1, tlasBuffer_, nullptr);
  tlasAddress_ = addressOf(ctx, tlas_);
  buildMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

AccelerationStructures::~AccelerationStructures() {
  if (tlas_) ctx_.rt().destroyAccelerationStructure(ctx_.device(), tlas_, nullptr);
  if (blas_) ctx_.rt().destroyAccelerationStructure(ctx_.device(), blas_, nullptr);
}

}  // namespace raylab
