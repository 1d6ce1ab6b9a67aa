#include "renderer/vk/validation_layer.h"

#include <cstring>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace raylab {

uint32_t validationLayerVersion() {
  uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  for (const auto& l : layers)
    if (std::strcmp(l.layerName, "VK_LAYER_KHRONOS_validation") == 0) return l.specVersion;
  return 0;
}

// Debian 12's layer (1.3.239) checks device addresses on lavapipe (the out-of-bounds proof on sort_copy is
// reported), but its instrumentation pass segfaults inside vkCreateShaderModule on every shader that
// includes path_state.glsl (generate, trace, shade, keys, key_learn, key_oracle, gather_path_state,
// heatmap_gather: they cast one buffer reference to another, directionBits), so no frame can be rendered.
std::string gpuAssistedUnavailable() {
  const uint32_t version = validationLayerVersion();
  if (version == 0) return "the Khronos validation layer is not installed";
  if (version <= VK_MAKE_API_VERSION(0, 1, 3, 239))
    return "GPU-assisted validation of layer " + std::to_string(VK_API_VERSION_MAJOR(version)) + "." +
           std::to_string(VK_API_VERSION_MINOR(version)) + "." + std::to_string(VK_API_VERSION_PATCH(version)) +
           " crashes instrumenting the path shaders (those that cast buffer references: path_state.glsl); "
           "run it with layer 1.4.309 (Debian 13) or newer";
  return "";
}

}  // namespace raylab
