// The window's swapchain: images the render is blitted into and the panels drawn over, recreated when the
// window's size changes. Images allow transfer writes (the blit) and, where the surface allows, transfer
// reads (Shift+F12 reads the finished window back).
#pragma once

#include <vector>

#include <vulkan/vulkan.h>

namespace raylab {

class VulkanContext;

class Swapchain {
 public:
  Swapchain(const VulkanContext& ctx, VkSurfaceKHR surface);
  ~Swapchain();
  Swapchain(const Swapchain&) = delete;
  Swapchain& operator=(const Swapchain&) = delete;

  // (Re)creates the images for a framebuffer of this size; the device must be idle.
  void recreate(uint32_t width, uint32_t height);
  // VK_SUCCESS, VK_SUBOPTIMAL_KHR or VK_ERROR_OUT_OF_DATE_KHR (recreate); other errors throw.
  VkResult acquire(VkSemaphore signal, uint32_t* index);
  VkResult present(VkSemaphore wait, uint32_t index);

  VkFormat format() const { return format_; }
  VkExtent2D extent() const { return extent_; }
  uint32_t minImageCount() const { return minImageCount_; }
  uint32_t imageCount() const { return static_cast<uint32_t>(images_.size()); }
  VkImage image(uint32_t i) const { return images_[i]; }
  VkImageView view(uint32_t i) const { return views_[i]; }
  bool readable() const { return readable_; }
  // True when the format stores blue in the first byte (screenshots swap it back to RGBA).
  bool bgr() const { return format_ == VK_FORMAT_B8G8R8A8_UNORM; }

 private:
  void chooseFormat();
  void destroyViews();

  const VulkanContext& ctx_;
  VkSurfaceKHR surface_;
  VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
  VkFormat format_ = VK_FORMAT_UNDEFINED;
  VkColorSpaceKHR colorSpace_ = VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
  VkPresentModeKHR presentMode_ = VK_PRESENT_MODE_FIFO_KHR;
  VkExtent2D extent_{0, 0};
  uint32_t minImageCount_ = 2;
  bool readable_ = false;
  std::vector<VkImage> images_;
  std::vector<VkImageView> views_;
};

}  // namespace raylab
