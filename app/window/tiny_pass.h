// An empty render pass on a 1x1 image, recorded before each render submission of the window (LiveRender). lavapipe
// runs a raster scene over the bound framebuffer at every timestamp (GpuTimer's flushes); after the UI
// pass that framebuffer is the whole window, and those scenes took 5-11% of the frame between the stage
// scopes. Binding a 1x1 framebuffer first makes them nearly free. Other devices ignore an empty pass.
#pragma once

#include <vulkan/vulkan.h>

namespace raylab {

class VulkanContext;

class TinyPass {
 public:
  explicit TinyPass(const VulkanContext& ctx);
  ~TinyPass();
  TinyPass(const TinyPass&) = delete;
  TinyPass& operator=(const TinyPass&) = delete;
  void record(VkCommandBuffer cmd) const;

 private:
  const VulkanContext& ctx_;
  VkImage image_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkImageView view_ = VK_NULL_HANDLE;
  VkRenderPass pass_ = VK_NULL_HANDLE;
  VkFramebuffer framebuffer_ = VK_NULL_HANDLE;
};

}  // namespace raylab
