#pragma once
// The one place that knows which Dear ImGui Vulkan backend it is built against. Debian 12 ships ImGui 1.86,
// Debian 13 ships 1.90.1; the backend's font upload changed in 1.90.0: CreateFontsTexture() records and
// submits its own command buffer and frees its staging buffer itself (DestroyFontUploadObjects is gone).
#include <imgui.h>
#include <imgui_impl_vulkan.h>

#include "renderer/vk/vk_context.h"

namespace raylab {

// Uploads the font atlas to the GPU and releases the upload's staging memory.
inline void uploadImGuiFonts(const VulkanContext& ctx) {
#if IMGUI_VERSION_NUM >= 19000
  (void)ctx;
  ImGui_ImplVulkan_CreateFontsTexture();
#else
  ctx.submitAndWait([](VkCommandBuffer cmd) { ImGui_ImplVulkan_CreateFontsTexture(cmd); });
  ImGui_ImplVulkan_DestroyFontUploadObjects();
#endif
}

}  // namespace raylab
