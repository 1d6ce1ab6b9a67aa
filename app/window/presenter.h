// One frame on screen: the path tracer's frame, its image copied and blitted full-window, the panels drawn
// over it, optionally the finished window read back (Shift+F12), then presented. One frame in flight: the
// renderer's statistics are read after each frame completes anyway.
#pragma once

#include <memory>
#include <vector>

#include <vulkan/vulkan.h>

#include "renderer/vk/gpu_buffer.h"

struct ImDrawData;

namespace raylab {

class VulkanContext;
class Swapchain;
class ImGuiLayer;
class PathTracer;
class RenderImage;
class TinyPass;

struct PresentedFrame {
  bool rendered = false;       // false: the swapchain was out of date, nothing was drawn
  bool recreateSwapchain = false;
  double wallMs = 0.0;         // submit to completion
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
  PresentedFrame drawFrame(PathTracer& tracer, ImDrawData* ui, bool captureWindow, bool nearest);
  // Call after the swapchain was recreated (new image count).
  void onSwapchainRecreated();

 private:
  void record(VkCommandBuffer cmd, PathTracer& tracer, ImDrawData* ui, uint32_t index, bool capture, bool nearest);
  void recordBlit(VkCommandBuffer cmd, PathTracer& tracer, uint32_t index, bool nearest);
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
  std::unique_ptr<TinyPass> tinyPass_;  // binds a 1x1 framebuffer before the frame (tiny_pass.h says why)
  GpuBuffer capture_;
};

}  // namespace raylab
