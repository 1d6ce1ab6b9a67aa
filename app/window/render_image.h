// The render as an image: the path tracer writes a buffer of RGBA8 pixels; blitting to the swapchain (and
// scaling to the window) needs an image, so each frame copies the buffer into this one first.
#pragma once

#include <vulkan/vulkan.h>

namespace raylab {

class VulkanContext;

class RenderImage {
 public:
  RenderImage(const VulkanContext& ctx, uint32_t width, uint32_t height);
  ~RenderImage();
  RenderImage(const RenderImage&) = delete;
  RenderImage& operator=(const RenderImage&) = delete;

  VkImage handle() const { return image_; }
  uint32_t width() const { return width_; }
  uint32_t height() const { return height_; }

 private:
  const VulkanContext& ctx_;
  VkImage image_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  uint32_t width_, height_;
};

}  // namespace raylab
