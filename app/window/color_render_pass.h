// A render pass of one colour attachment and one subpass, the only kind the window uses (the UI pass over
// the swapchain image, and the empty 1x1 pass that keeps lavapipe's timestamps cheap).
#pragma once

#include <vulkan/vulkan.h>

namespace raylab {

struct ColorPassSpec {
  VkFormat format;
  VkAttachmentLoadOp load;
  VkAttachmentStoreOp store;
  VkImageLayout initialLayout;
  VkImageLayout finalLayout;
};

VkRenderPass createColorRenderPass(VkDevice device, const ColorPassSpec& spec);

}  // namespace raylab
