// Dear ImGui in the window: the context with its imgui.ini (ImGuiSession), and the GLFW and Vulkan
// backends drawing the panels in a render pass that loads the blitted render and draws over it.
#pragma once

#include <string>
#include <vector>

#include <vulkan/vulkan.h>

struct GLFWwindow;
struct ImDrawData;

namespace raylab {

class VulkanContext;
class Swapchain;
struct IniState;

// The ImGui context. Registers the lab's imgui.ini section in `ini` and reads the file now (before the
// window exists: it holds the window's size and the settings to start from), unless `load` is false.
// An empty path keeps no imgui.ini at all.
class ImGuiSession {
 public:
  ImGuiSession(const std::string& iniPath, bool load, IniState* ini);
  ~ImGuiSession();
  ImGuiSession(const ImGuiSession&) = delete;
  ImGuiSession& operator=(const ImGuiSession&) = delete;

 private:
  std::string iniPath_;  // ImGui keeps the pointer
};

class ImGuiLayer {
 public:
  // Installs the GLFW backend's callbacks: install the window's own first, the backend chains them.
  ImGuiLayer(const VulkanContext& ctx, GLFWwindow* window, const Swapchain& swapchain);
  ~ImGuiLayer();
  ImGuiLayer(const ImGuiLayer&) = delete;
  ImGuiLayer& operator=(const ImGuiLayer&) = delete;

  // After the swapchain was recreated (the device is idle).
  void onSwapchainRecreated(const Swapchain& swapchain);
  // Starts a frame: backends, then ImGui::NewFrame.
  void newFrame();
  // Records the render pass drawing `data` over swapchain image `index`, which must be in
  // COLOR_ATTACHMENT_OPTIMAL layout; it stays in that layout.
  void record(VkCommandBuffer cmd, uint32_t index, ImDrawData* data);

 private:
  void createRenderPass(VkFormat format);
  void createFramebuffers(const Swapchain& swapchain);
  void destroyFramebuffers();

  const VulkanContext& ctx_;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  VkRenderPass renderPass_ = VK_NULL_HANDLE;
  std::vector<VkFramebuffer> framebuffers_;
  VkExtent2D extent_{0, 0};
};

}  // namespace raylab
