// The Vulkan instance, the chosen physical device and one queue that does compute (and graphics, for the
// window). Built for compute without a window; the window adds instance and device extensions.
#pragma once

#include <atomic>
#include <functional>
#include <mutex>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "renderer/vk/validation_mode.h"

namespace raylab {

struct ContextOptions {
  // VK_LAYER_KHRONOS_validation with synchronization or GPU-assisted validation, its messages counted.
  ValidationMode validation = ValidationMode::Off;
  std::string deviceName;          // substring of the device name to pick, or digits: the Nth device of
                                   // `raylab devices` (0-based); empty: discrete GPU, else any
  std::vector<const char*> instanceExtensions;  // e.g. from glfwGetRequiredInstanceExtensions
  std::vector<const char*> deviceExtensions;    // e.g. VK_KHR_swapchain
  bool quiet = false;              // do not print the chosen device
};

struct DeviceInfo {
  std::string name;
  std::string driver;
  // Which device of the host this is, for result rows of GPUs that share a name: its number in
  // `raylab devices` (what --device N picks), its Vulkan device UUID (hex), and its PCI address
  // (domain:bus:device.function, VK_EXT_pci_bus_info; empty where the driver lacks it, as lavapipe does).
  uint32_t number = 0;
  std::string uuid;
  std::string pciBus;
  uint32_t vendorId = 0;
  uint32_t subgroupSize = 0;
  float timestampPeriodNs = 0.0f;
  bool timestamps = false;
  uint32_t maxGroupCountX = 0;  // maxComputeWorkGroupCount[0] and [1]
  uint32_t maxGroupCountY = 0;
  // The row length of every dispatch made from a thread count (renderer/vk/dispatch_size.h), written into
  // GpuFrame for the indirect sizes shaders make: maxGroupCountX, or what setDispatchRowGroups set.
  uint32_t dispatchRowGroups = 0;
  uint64_t maxMemoryAllocationSize = 0;  // VkPhysicalDeviceMaintenance3Properties (0: not known)
  bool isCpu = false;
  // VK_NV_shader_subgroup_partitioned, enabled where the device has it (NVIDIA): subgroupPartitionNV, the
  // radix scatter's one-instruction ranking (GpuSorter::Tuning::radixRankPartitioned).
  bool subgroupPartitioned = false;
  // VK_KHR_pipeline_executable_properties enabled for RAYLAB_SHADER_STATS (pipeline_statistics.h).
  bool shaderStatistics = false;

  // Hardware-API ray tracing (the rt tracer): VK_KHR_acceleration_structure and VK_KHR_ray_tracing_pipeline
  // with their features, enabled whenever the device has them. rayTracingMissing names what is missing.
  bool rayTracing = false;
  std::string rayTracingMissing;
  bool subgroupsInRayGen = false;  // subgroup operations in ray-generation shaders
  uint32_t shaderGroupHandleSize = 0;
  uint32_t shaderGroupHandleAlignment = 0;
  uint32_t shaderGroupBaseAlignment = 0;
  uint32_t maxRayDispatchInvocationCount = 0;
  uint32_t minAccelerationStructureScratchOffsetAlignment = 0;
  // Shader Execution Reordering (VK_NV_ray_tracing_invocation_reorder), enabled when present; serMissing
  // names what is missing. serReorderingHint is the device's VkRayTracingInvocationReorderModeNV:
  // "reorder" (it may reorder) or "none" (reorderThreadNV is a no-op on this device).
  bool ser = false;
  std::string serMissing;
  std::string serReorderingHint = "n/a";
};

// Entry points of the ray-tracing extensions (the loader exports only core functions).
struct RayTracingFunctions {
  PFN_vkCreateAccelerationStructureKHR createAccelerationStructure = nullptr;
  PFN_vkDestroyAccelerationStructureKHR destroyAccelerationStructure = nullptr;
  PFN_vkGetAccelerationStructureBuildSizesKHR getAccelerationStructureBuildSizes = nullptr;
  PFN_vkCmdBuildAccelerationStructuresKHR cmdBuildAccelerationStructures = nullptr;
  PFN_vkGetAccelerationStructureDeviceAddressKHR getAccelerationStructureDeviceAddress = nullptr;
  PFN_vkCmdCopyAccelerationStructureKHR cmdCopyAccelerationStructure = nullptr;
  PFN_vkCmdWriteAccelerationStructuresPropertiesKHR cmdWriteAccelerationStructuresProperties = nullptr;
  PFN_vkCreateRayTracingPipelinesKHR createRayTracingPipelines = nullptr;
  PFN_vkGetRayTracingShaderGroupHandlesKHR getRayTracingShaderGroupHandles = nullptr;
  PFN_vkCmdTraceRaysKHR cmdTraceRays = nullptr;
};

class VulkanContext {
 public:
  explicit VulkanContext(const ContextOptions& options);
  ~VulkanContext();
  VulkanContext(const VulkanContext&) = delete;
  VulkanContext& operator=(const VulkanContext&) = delete;

  VkInstance instance() const { return instance_; }
  VkPhysicalDevice physicalDevice() const { return physical_; }
  VkDevice device() const { return device_; }
  VkQueue queue() const { return queue_; }
  uint32_t queueFamily() const { return queueFamily_; }
  const DeviceInfo& info() const { return info_; }
  // Tests: dispatches from now on run in rows of `groups` work groups (0: the device's limit), so that small
  // renders run on several rows, as large ones do on every device. Read at every dispatch and frame. (A
  // second context for this crashed at exit on Debian 13's lavapipe and layer, once two instances had lived.)
  void setDispatchRowGroups(uint32_t groups);
  // Valid only when info().rayTracing.
  const RayTracingFunctions& rt() const { return rt_; }

  // Records commands into a one-time command buffer, submits it and waits for completion.
  void submitAndWait(const std::function<void(VkCommandBuffer)>& record) const;

  // Validation messages of severity warning or error seen so far (tests fail on any error).
  uint32_t validationErrors() const { return validationErrors_.load(); }
  uint32_t validationWarnings() const { return validationWarnings_.load(); }
  // The message id and text of the latest validation error ("" before any): what a test that provokes one
  // checks it got.
  std::string lastValidationError() const;
  uint32_t findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags wanted) const;

  // For `raylab devices`: one line per device the loader sees: its name, and whether it has the rt tracer's and SER's extensions (which it lacks).
  static std::vector<std::string> describeDevices();

 private:
  void createInstance(const ContextOptions& options);
  void pickPhysicalDevice(const ContextOptions& options);
  void createDevice(const ContextOptions& options);
  static VKAPI_ATTR VkBool32 VKAPI_CALL onValidationMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                            VkDebugUtilsMessageTypeFlagsEXT types,
                                                            const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                            void* user);

  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  uint32_t queueFamily_ = 0;
  VkCommandPool commandPool_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
  DeviceInfo info_;
  RayTracingFunctions rt_;
  VkPhysicalDeviceMemoryProperties memoryProperties_{};
  std::atomic<uint32_t> validationErrors_{0};
  std::atomic<uint32_t> validationWarnings_{0};
  mutable std::mutex lastErrorMutex_;  // the layer may call back from any thread
  std::string lastError_;
};

}  // namespace raylab
