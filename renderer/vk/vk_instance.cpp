// The instance and the validation layer: VulkanContext::createInstance and the messenger that counts the
// layer's messages (vk_context.cpp makes the device).
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "renderer/vk/validation_layer.h"
#include "renderer/vk/vk_check.h"
#include "renderer/vk/vk_context.h"

namespace raylab {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

bool hasLayer(const char* name) {
  uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  for (const auto& l : layers)
    if (std::strcmp(l.layerName, name) == 0) return true;
  return false;
}

bool layerHasExtension(const char* layer, const char* extension) {
  uint32_t count = 0;
  vkEnumerateInstanceExtensionProperties(layer, &count, nullptr);
  std::vector<VkExtensionProperties> extensions(count);
  vkEnumerateInstanceExtensionProperties(layer, &count, extensions.data());
  for (const auto& e : extensions)
    if (std::strcmp(e.extensionName, extension) == 0) return true;
  return false;
}

}  // namespace

VKAPI_ATTR VkBool32 VKAPI_CALL VulkanContext::onValidationMessage(
    VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT,
    const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  auto* self = static_cast<VulkanContext*>(user);
  if (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) {
    {
      std::lock_guard<std::mutex> lock(self->lastErrorMutex_);
      self->lastError_ = std::string(data->pMessageIdName ? data->pMessageIdName : "") + ": " + data->pMessage;
    }
    self->validationErrors_++;
    std::fprintf(stderr, "validation error: %s\n", data->pMessage);
  } else if (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) {
    self->validationWarnings_++;
    std::fprintf(stderr, "validation warning: %s\n", data->pMessage);
  }
  return VK_FALSE;
}

void VulkanContext::createInstance(const ContextOptions& options) {
  std::vector<const char*> extensions = options.instanceExtensions;
  std::vector<const char*> layers;
  const bool validate = options.validation != ValidationMode::Off;
  if (validate) {
    if (!hasLayer(kValidationLayer))
      throw VulkanError("--validate: the Khronos validation layer is not installed (apt-get install "
                        "vulkan-validationlayers)");
    if (options.validation == ValidationMode::GpuAssisted)
      if (std::string why = gpuAssistedUnavailable(); !why.empty())
        std::fprintf(stderr, "raylab: warning: %s\n", why.c_str());
    layers.push_back(kValidationLayer);
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    // VkValidationFeaturesEXT below is an extension structure: the layer provides its extension.
    if (layerHasExtension(kValidationLayer, VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME))
      extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
  }
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "raylab";
  app.apiVersion = VK_API_VERSION_1_2;

  VkDebugUtilsMessengerCreateInfoEXT messengerInfo{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  messengerInfo.messageSeverity =
      VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  messengerInfo.pfnUserCallback = &VulkanContext::onValidationMessage;
  messengerInfo.pUserData = this;

  // Beyond the core checks: synchronization validation (hazards between commands that lack a barrier) or
  // GPU-assisted validation (instrumented shaders check every buffer-device-address access). The layer
  // refuses both in one instance, hence one mode or the other (ValidationMode). VkValidationFeaturesEXT is
  // read by both the 1.3.239 (Debian 12) and 1.4.309 (Debian 13) layers.
  const VkValidationFeatureEnableEXT enabled = options.validation == ValidationMode::GpuAssisted
                                                   ? VK_VALIDATION_FEATURE_ENABLE_GPU_ASSISTED_EXT
                                                   : VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;
  VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
  features.pNext = &messengerInfo;
  features.enabledValidationFeatureCount = 1;
  features.pEnabledValidationFeatures = &enabled;

  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pNext = validate ? &features : nullptr;
  info.pApplicationInfo = &app;
  info.enabledLayerCount = static_cast<uint32_t>(layers.size());
  info.ppEnabledLayerNames = layers.data();
  info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  VK_CHECK(vkCreateInstance(&info, nullptr, &instance_));

  if (validate) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
    if (!create) throw VulkanError("vkCreateDebugUtilsMessengerEXT is unavailable");
    VK_CHECK(create(instance_, &messengerInfo, nullptr, &messenger_));
  }
}

std::string VulkanContext::lastValidationError() const {
  std::lock_guard<std::mutex> lock(lastErrorMutex_);
  return lastError_;
}

}  // namespace raylab
