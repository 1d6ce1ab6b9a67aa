#include "app/window/swapchain.h"

#include <algorithm>

#include "renderer/vk/vk_check.h"
#include "renderer/vk/vk_context.h"

namespace raylab {

Swapchain::Swapchain(const VulkanContext& ctx, VkSurfaceKHR surface) : ctx_(ctx), surface_(surface) {
  chooseFormat();
  uint32_t count = 0;
  vkGetPhysicalDeviceSurfacePresentModesKHR(ctx.physicalDevice(), surface, &count, nullptr);
  std::vector<VkPresentModeKHR> modes(count);
  vkGetPhysicalDeviceSurfacePresentModesKHR(ctx.physicalDevice(), surface, &count, modes.data());
  // The lab measures frame times: do not wait for vertical blank where the surface lets us.
  for (VkPresentModeKHR wanted : {VK_PRESENT_MODE_MAILBOX_KHR, VK_PRESENT_MODE_IMMEDIATE_KHR})
    if (std::find(modes.begin(), modes.end(), wanted) != modes.end()) {
      presentMode_ = wanted;
      break;
    }
}

Swapchain::~Swapchain() {
  destroyViews();
  if (swapchain_) vkDestroySwapchainKHR(ctx_.device(), swapchain_, nullptr);
}

// UNORM, not sRGB: the render is already tonemapped and encoded, and the blit must copy it unchanged.
void Swapchain::chooseFormat() {
  uint32_t count = 0;
  vkGetPhysicalDeviceSurfaceFormatsKHR(ctx_.physicalDevice(), surface_, &count, nullptr);
  std::vector<VkSurfaceFormatKHR> formats(count);
  vkGetPhysicalDeviceSurfaceFormatsKHR(ctx_.physicalDevice(), surface_, &count, formats.data());
  for (VkFormat wanted : {VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM})
    for (const VkSurfaceFormatKHR& f : formats) {
      VkFormatProperties props;
      vkGetPhysicalDeviceFormatProperties(ctx_.physicalDevice(), f.format, &props);
      if (f.format == wanted && (props.optimalTilingFeatures & VK_FORMAT_FEATURE_BLIT_DST_BIT)) {
        format_ = f.format;
        colorSpace_ = f.colorSpace;
        return;
      }
    }
  throw VulkanError("the window surface offers no 8-bit UNORM format the render can be blitted into");
}

void Swapchain::destroyViews() {
  for (VkImageView v : views_) vkDestroyImageView(ctx_.device(), v, nullptr);
  views_.clear();
}

void Swapchain::recreate(uint32_t width, uint32_t height) {
  VkSurfaceCapabilitiesKHR caps;
  VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(ctx_.physicalDevice(), surface_, &caps));
  extent_ = caps.currentExtent.width != UINT32_MAX
                ? caps.currentExtent
                : VkExtent2D{std::clamp(width, caps.minImageExtent.width, caps.maxImageExtent.width),
                             std::clamp(height, caps.minImageExtent.height, caps.maxImageExtent.height)};
  minImageCount_ = std::max(2u, caps.minImageCount + 1);
  if (caps.maxImageCount > 0) minImageCount_ = std::min(minImageCount_, caps.maxImageCount);
  readable_ = (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT) != 0;

  VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
  info.surface = surface_;
  info.minImageCount = minImageCount_;
  info.imageFormat = format_;
  info.imageColorSpace = colorSpace_;
  info.imageExtent = extent_;
  info.imageArrayLayers = 1;
  info.imageUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                    (readable_ ? VK_IMAGE_USAGE_TRANSFER_SRC_BIT : 0);
  info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.preTransform = caps.currentTransform;
  info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
  if (!(caps.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR))
    info.compositeAlpha = static_cast<VkCompositeAlphaFlagBitsKHR>(caps.supportedCompositeAlpha & -caps.supportedCompositeAlpha);
  info.presentMode = presentMode_;
  info.clipped = VK_TRUE;
  info.oldSwapchain = swapchain_;
  VkSwapchainKHR created = VK_NULL_HANDLE;
  VK_CHECK(vkCreateSwapchainKHR(ctx_.device(), &info, nullptr, &created));
  destroyViews();
  if (swapchain_) vkDestroySwapchainKHR(ctx_.device(), swapchain_, nullptr);
  swapchain_ = created;

  uint32_t count = 0;
  VK_CHECK(vkGetSwapchainImagesKHR(ctx_.device(), swapchain_, &count, nullptr));
  images_.resize(count);
  VK_CHECK(vkGetSwapchainImagesKHR(ctx_.device(), swapchain_, &count, images_.data()));
  for (VkImage image : images_) {
    VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view.image = image;
    view.viewType = VK_IMAGE_VIEW_TYPE_2D;
    view.format = format_;
    view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    views_.push_back(VK_NULL_HANDLE);
    VK_CHECK(vkCreateImageView(ctx_.device(), &view, nullptr, &views_.back()));
  }
}

VkResult Swapchain::acquire(VkSemaphore signal, uint32_t* index) {
  VkResult r = vkAcquireNextImageKHR(ctx_.device(), swapchain_, UINT64_MAX, signal, VK_NULL_HANDLE, index);
  if (r != VK_SUCCESS && r != VK_SUBOPTIMAL_KHR && r != VK_ERROR_OUT_OF_DATE_KHR)
    throw VulkanError("vkAcquireNextImageKHR failed: " + vkResultName(r));
  return r;
}

VkResult Swapchain::present(VkSemaphore wait, uint32_t index) {
  VkPresentInfoKHR info{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
  info.waitSemaphoreCount = 1;
  info.pWaitSemaphores = &wait;
  info.swapchainCount = 1;
  info.pSwapchains = &swapchain_;
  info.pImageIndices = &index;
  VkResult r = vkQueuePresentKHR(ctx_.queue(), &info);
  if (r != VK_SUCCESS && r != VK_SUBOPTIMAL_KHR && r != VK_ERROR_OUT_OF_DATE_KHR)
    throw VulkanError("vkQueuePresentKHR failed: " + vkResultName(r));
  return r;
}

}  // namespace raylab
