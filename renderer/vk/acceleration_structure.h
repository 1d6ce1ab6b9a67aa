// The rt tracer's acceleration structures: one bottom-level structure over the scene's triangles (opaque,
// non-indexed, in the order the shaders index them, so gl_PrimitiveID is that index), compacted, and a
// top-level structure with one instance of it (identity transform, no face culling: two-sided surfaces).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>
#include <vulkan/vulkan.h>

#include "renderer/vk/gpu_buffer.h"

namespace raylab {

class VulkanContext;

class AccelerationStructures {
 public:
  // `vertices`: three per triangle. Builds (and compacts) on the queue before returning.
  AccelerationStructures(const VulkanContext& ctx, const std::vector<glm::vec3>& vertices);
  ~AccelerationStructures();
  AccelerationStructures(const AccelerationStructures&) = delete;
  AccelerationStructures& operator=(const AccelerationStructures&) = delete;

  VkDeviceAddress tlasAddress() const { return tlasAddress_; }
  uint64_t bytes() const { return blasBuffer_.size() + tlasBuffer_.size(); }
  uint64_t blasBytesBeforeCompaction() const { return blasBytesUncompacted_; }
  double buildMs() const { return buildMs_; }

 private:
  const VulkanContext& ctx_;
  GpuBuffer blasBuffer_, tlasBuffer_;
  VkAccelerationStructureKHR blas_ = VK_NULL_HANDLE, tlas_ = VK_NULL_HANDLE;
  VkDeviceAddress tlasAddress_ = 0;
  uint64_t blasBytesUncompacted_ = 0;
  double buildMs_ = 0.0;
};

}  // namespace raylab
