// One UI frame on screen: the shown render image (LiveRender: the render's, or a coarse preview) copied into
// an image when it changed and blitted full-window, the panels drawn over it, optionally the finished window
// read back (Shift+F12), then presented. The render's own work is submitted apart (LiveRender), so this
// submission is only the UI's. One frame in flight.
#pragma once

#include <memory>
#include <vector>

#include <vulkan/vulkan.h>

#include "app/window/live_render.h"
#include "renderer/vk/gpu_buffer.h"

struct ImDrawData;

namespace raylab {

class VulkanContext;
class Swapchain;
class ImGuiLayer;
class RenderImage;

struct PresentedFrame {
  bool rendered = false;       // false: the swapchain was out of date, nothing was drawn
  bool recreateSwapchain = false;
  double wallMs = 0.0;         // submit to completion (the blit and the panels)
  std::vector<uint32_t> window;  // RGBA8 of the whole window when it was captured
  uint32_t windowWidth = 0, windowHeight = 0;
};

class Presenter {
 public:
  Presenter(const VulkanContext& ctx, Swapchain& swapchain, ImGuiLayer& layer);
  ~Presenter();
  Presenter(const Presenter&) = delete;
  Presenter& operator=(const Presenter&) = delete;

  // `nearest` blits without filtering (heatmaps: a pixel's colour is data, not to be blended).
  PresentedFrame drawFrame(const ShownImage& shown, ImDrawData* ui, bool captureWindow, bool nearest);
  // Call after the swapchain was recreated (new image count).
  void onSwapchainRecreated();

 private:
  void record(VkCommandBuffer cmd, const ShownImage& shown, ImDrawData* ui, uint32_t index, bool capture, bool nearest);
  void recordCopy(VkCommandBuffer cmd, const ShownImage& shown);
  void recordBlit(VkCommandBuffer cmd, uint32_t index, bool nearest);
  void recordCapture(VkCommandBuffer cmd, uint32_t index);
  std::vector<uint32_t> readCapture() const;

  const VulkanContext& ctx_;
  Swapchain& swapchain_;
  ImGuiLayer& layer_;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  VkCommandBuffer cmd_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
  VkSemaphore acquired_ = VK_NULL_HANDLE;
  std::vector<VkSemaphore> rendered_;  // one per swapchain image: presentation may still hold the last one
  std::unique_ptr<RenderImage> image_;
  uint64_t imageVersion_ = 0;  // ShownImage::version of what image_ holds (0: nothing yet)
  GpuBuffer capture_;
};

}  // namespace raylab
