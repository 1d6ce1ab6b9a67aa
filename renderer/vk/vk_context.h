// The Vulkan instance, the chosen physical device and one queue that does compute (and graphics, for the
// window). Built for compute without a window; the window adds instance and device extensions.
#pragma once

#include <atomic>
#include <functional>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace raylab {

struct ContextOptions {
  bool validate = false;           // enable VK_LAYER_KHRONOS_validation and count its messages
  std::string deviceName;          // substring of the device name to pick; empty: discrete GPU, else any
  std::vector<const char*> instanceExtensions;  // e.g. from glfwGetRequiredInstanceExtensions
  std::vector<const char*> deviceExtensions;    // e.g. VK_KHR_swapchain
  bool quiet = false;              // do not print the chosen device
};

struct DeviceInfo {
  std::string name;
  std::string driver;
  uint32_t vendorId = 0;
  uint32_t subgroupSize = 0;
  float timestampPeriodNs = 0.0f;
  bool timestamps = false;
  uint32_t maxGroupCountX = 0;
  bool isCpu = false;
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

  // Records commands into a one-time command buffer, submits it and waits for completion.
  void submitAndWait(const std::function<void(VkCommandBuffer)>& record) const;

  // Validation messages of severity warning or error seen so far (tests fail on any error).
  uint32_t validationErrors() const { return validationErrors_.load(); }
  uint32_t validationWarnings() const { return validationWarnings_.load(); }
  uint32_t findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags wanted) const;

  // Names of all devices the loader sees (for --device errors and `raylab devices`).
  static std::vector<std::string> listDevices();

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
  VkPhysicalDeviceMemoryProperties memoryProperties_{};
  std::atomic<uint32_t> validationErrors_{0};
  std::atomic<uint32_t> validationWarnings_{0};
};

}  // namespace raylab
