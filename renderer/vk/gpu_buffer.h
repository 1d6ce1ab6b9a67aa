// A Vulkan buffer with its own memory, addressed from shaders by device address. Move-only.
// Device-local buffers are filled and read through a temporary staging buffer; host-visible ones are
// mapped for their whole life (readback rings, small parameter blocks).
#pragma once

#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

namespace raylab {

class VulkanContext;

enum class MemoryKind { DeviceLocal, HostVisible };

class GpuBuffer {
 public:
  GpuBuffer() = default;
  // `extraUsage` adds usages beyond storage, transfer, device address and indirect (acceleration-structure
  // storage and build input, shader binding tables). `memoryBytes` allocates more memory than the buffer
  // needs, the buffer at its start: the rest is mapped memory outside every buffer (the GPU-AV proof reads it).
  GpuBuffer(const VulkanContext& ctx, VkDeviceSize bytes, MemoryKind kind = MemoryKind::DeviceLocal,
            VkBufferUsageFlags extraUsage = 0, VkDeviceSize memoryBytes = 0);
  ~GpuBuffer();
  GpuBuffer(GpuBuffer&& other) noexcept;
  GpuBuffer& operator=(GpuBuffer&& other) noexcept;
  GpuBuffer(const GpuBuffer&) = delete;
  GpuBuffer& operator=(const GpuBuffer&) = delete;

  VkBuffer handle() const { return buffer_; }
  VkDeviceAddress address() const { return address_; }
  VkDeviceSize size() const { return size_; }
  bool valid() const { return buffer_ != VK_NULL_HANDLE; }
  void* mapped() const { return mapped_; }

  void upload(const void* data, VkDeviceSize bytes, VkDeviceSize offset = 0);
  void download(void* out, VkDeviceSize bytes, VkDeviceSize offset = 0) const;
  // Records a fill of the whole buffer with a 32-bit pattern.
  void recordFill(VkCommandBuffer cmd, uint32_t value) const;

  template <class T>
  void uploadVector(const std::vector<T>& v) { upload(v.data(), v.size() * sizeof(T)); }
  template <class T>
  std::vector<T> downloadVector(size_t count) const {
    std::vector<T> v(count);
    download(v.data(), count * sizeof(T));
    return v;
  }

 private:
  void release();

  const VulkanContext* ctx_ = nullptr;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkDeviceAddress address_ = 0;
  VkDeviceSize size_ = 0;
  void* mapped_ = nullptr;
};

// Makes a device-local buffer holding a copy of `v` (at least 16 bytes, so empty arrays still have an address).
template <class T>
GpuBuffer makeBufferFrom(const VulkanContext& ctx, const std::vector<T>& v) {
  GpuBuffer b(ctx, v.size() * sizeof(T));
  if (!v.empty()) b.uploadVector(v);
  return b;
}

}  // namespace raylab
