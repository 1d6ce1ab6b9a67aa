#include "app/window/color_render_pass.h"

#include "renderer/vk/vk_check.h"

namespace raylab {

VkRenderPass createColorRenderPass(VkDevice device, const ColorPassSpec& spec) {
  VkAttachmentDescription color{};
  color.format = spec.format;
  color.samples = VK_SAMPLE_COUNT_1_BIT;
  color.loadOp = spec.load;
  color.storeOp = spec.store;
  color.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  color.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  color.initialLayout = spec.initialLayout;
  color.finalLayout = spec.finalLayout;
  VkAttachmentReference ref{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &ref;
  VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  info.attachmentCount = 1;
  info.pAttachments = &color;
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  VkRenderPass pass;
  VK_CHECK(vkCreateRenderPass(device, &info, nullptr, &pass));
  return pass;
}

}  // namespace raylab
