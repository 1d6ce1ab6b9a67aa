// The rt tracer's and SER's device support, probed apart from device creation: which extensions and
// features the device has, what the context therefore enables, and the properties the rt tracer reads.
// VulkanContext::createDevice chains what this enables into its VkDeviceCreateInfo.
#pragma once

#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "renderer/vk/vk_context.h"

namespace raylab {

// The extensions the rt tracer needs (VK_KHR_ray_tracing_pipeline and what it requires), and SER's.
extern const std::vector<const char*> kRayTracingExtensions;
extern const std::vector<const char*> kSerExtensions;

// The names of `wanted` that `physical` lacks, comma-separated ("" when it has them all).
std::string missingDeviceExtensions(VkPhysicalDevice physical, const std::vector<const char*>& wanted);

class RayTracingSupport {
 public:
  // Probes `physical` and fills `info`'s ray-tracing and SER fields (rayTracing, ser, what is missing,
  // the pipeline and acceleration-structure properties).
  RayTracingSupport(VkPhysicalDevice physical, DeviceInfo& info);
  // The feature structs point at each other: not copyable.
  RayTracingSupport(const RayTracingSupport&) = delete;
  RayTracingSupport& operator=(const RayTracingSupport&) = delete;

  // The device extensions to enable (none without ray tracing).
  const std::vector<const char*>& extensions() const { return extensions_; }
  // The head of the feature chain to enable, for a pNext (nullptr without ray tracing). Valid while this lives.
  void* features() { return extensions_.empty() ? nullptr : &accelerationStructure_; }

 private:
  void readProperties(VkPhysicalDevice physical, DeviceInfo& info) const;

  std::vector<const char*> extensions_;
  VkPhysicalDeviceAccelerationStructureFeaturesKHR accelerationStructure_{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR};
  VkPhysicalDeviceRayTracingPipelineFeaturesKHR pipeline_{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR};
  VkPhysicalDeviceRayTracingInvocationReorderFeaturesNV reorder_{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_INVOCATION_REORDER_FEATURES_NV};
};

// The ray-tracing entry points of `device` (the loader exports only core functions); throws if one is absent.
RayTracingFunctions loadRayTracingFunctions(VkDevice device);

}  // namespace raylab
