// Vulkan error handling: every call that can fail goes through VK_CHECK, which throws with the call's text,
// so a failure anywhere surfaces as one clear message instead of a crash later.
#pragma once

#include <stdexcept>
#include <string>

#include <vulkan/vulkan.h>

namespace raylab {

struct VulkanError : std::runtime_error {
  using std::runtime_error::runtime_error;
};
// --device names no device: a bad command line (exit 2), not a failure of the device.
struct UnknownDeviceError : VulkanError {
  using VulkanError::VulkanError;
};

std::string vkResultName(VkResult r);

}  // namespace raylab

#define VK_CHECK(call)                                                                         \
  do {                                                                                         \
    VkResult vk_check_result_ = (call);                                                        \
    if (vk_check_result_ != VK_SUCCESS)                                                        \
      throw ::raylab::VulkanError(std::string(#call) + " failed: " +                           \
                                  ::raylab::vkResultName(vk_check_result_));                   \
  } while (0)
