#include "renderer/vk/gpu_buffer.h"

#include <algorithm>
#include <cstring>
#include <utility>

#include "renderer/vk/vk_check.h"
#include "renderer/vk/vk_context.h"

namespace raylab {

GpuBuffer::GpuBuffer(const VulkanContext& ctx, VkDeviceSize bytes, MemoryKind kind, VkBufferUsageFlags extraUsage,
                     VkDeviceSize memoryBytes)
    : ctx_(&ctx) {
  size_ = std::max<VkDeviceSize>(bytes, 16);
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = size_;
  info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
               VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT |
               VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT | extraUsage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VK_CHECK(vkCreateBuffer(ctx.device(), &info, nullptr, &buffer_));

  VkMemoryRequirements req;
  vkGetBufferMemoryRequirements(ctx.device(), buffer_, &req);
  VkMemoryAllocateFlagsInfo flags{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_FLAGS_INFO};
  flags.flags = VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT;
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.pNext = &flags;
  alloc.allocationSize = std::max(req.size, memoryBytes);
  alloc.memoryTypeIndex = ctx.findMemoryType(
      req.memoryTypeBits, kind == MemoryKind::HostVisible
                              ? VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT
                              : VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  VkResult r = vkAllocateMemory(ctx.device(), &alloc, nullptr, &memory_);
  if (r != VK_SUCCESS) {
    vkDestroyBuffer(ctx.device(), buffer_, nullptr);
    buffer_ = VK_NULL_HANDLE;
    throw VulkanError("cannot allocate a buffer of " + std::to_string(bytes) + " bytes: " + vkResultName(r));
  }
  VK_CHECK(vkBindBufferMemory(ctx.device(), buffer_, memory_, 0));
  if (kind == MemoryKind::HostVisible) VK_CHECK(vkMapMemory(ctx.device(), memory_, 0, VK_WHOLE_SIZE, 0, &mapped_));
  VkBufferDeviceAddressInfo addressInfo{VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO};
  addressInfo.buffer = buffer_;
  address_ = vkGetBufferDeviceAddress(ctx.device(), &addressInfo);
}

GpuBuffer::~GpuBuffer() { release(); }

GpuBuffer::GpuBuffer(GpuBuffer&& o) noexcept { *this = std::move(o); }

GpuBuffer& GpuBuffer::operator=(GpuBuffer&& o) noexcept {
  if (this != &o) {
    release();
    ctx_ = std::exchange(o.ctx_, nullptr);
    buffer_ = std::exchange(o.buffer_, VK_NULL_HANDLE);
    memory_ = std::exchange(o.memory_, VK_NULL_HANDLE);
    address_ = std::exchange(o.address_, 0);
    size_ = std::exchange(o.size_, 0);
    mapped_ = std::exchange(o.mapped_, nullptr);
  }
  return *this;
}

void GpuBuffer::release() {
  if (!ctx_) return;
  if (buffer_) vkDestroyBuffer(ctx_->device(), buffer_, nullptr);
  if (memory_) vkFreeMemory(ctx_->device(), memory_, nullptr);
  buffer_ = VK_NULL_HANDLE;
  memory_ = VK_NULL_HANDLE;
  mapped_ = nullptr;
}

void GpuBuffer::upload(const void* data, VkDeviceSize bytes, VkDeviceSize offset) {
  if (bytes == 0) return;
  if (offset + bytes > size_) throw VulkanError("GpuBuffer::upload past the end of the buffer");
  if (mapped_) {
    std::memcpy(static_cast<char*>(mapped_) + offset, data, bytes);
    return;
  }
  GpuBuffer staging(*ctx_, bytes, MemoryKind::HostVisible);
  std::memcpy(staging.mapped(), data, bytes);
  ctx_->submitAndWait([&](VkCommandBuffer cmd) {
    VkBufferCopy copy{0, offset, bytes};
    vkCmdCopyBuffer(cmd, staging.handle(), buffer_, 1, &copy);
  });
}

void GpuBuffer::download(void* out, VkDeviceSize bytes, VkDeviceSize offset) const {
  if (bytes == 0) return;
  if (offset + bytes > size_) throw VulkanError("GpuBuffer::download past the end of the buffer");
  if (mapped_) {
    std::memcpy(out, static_cast<const char*>(mapped_) + offset, bytes);
    return;
  }
  GpuBuffer staging(*ctx_, bytes, MemoryKind::HostVisible);
  ctx_->submitAndWait([&](VkCommandBuffer cmd) {
    VkBufferCopy copy{offset, 0, bytes};
    vkCmdCopyBuffer(cmd, buffer_, staging.handle(), 1, &copy);
  });
  std::memcpy(out, staging.mapped(), bytes);
}

void GpuBuffer::recordFill(VkCommandBuffer cmd, uint32_t value) const {
  vkCmdFillBuffer(cmd, buffer_, 0, VK_WHOLE_SIZE, value);
}

}  // namespace raylab
