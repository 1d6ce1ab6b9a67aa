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
// An empty path keeps no imgui.ini at all. ImGui itself writes no file (io.IniFilename is null): the
// session saves imgui.ini through writeFileChecked, so a failed save is reported, never silent.
class ImGuiSession {
 public:
  ImGuiSession(const std::string& iniPath, bool load, IniState* ini);
  ~ImGuiSession();  // saves imgui.ini unless close() did (a failure then goes to stderr only)
  ImGuiSession(const ImGuiSession&) = delete;
  ImGuiSession& operator=(const ImGuiSession&) = delete;

  // Saves imgui.ini when ImGui asks for it (io.WantSaveIniSettings: a panel moved, at most every few
  // seconds); returns the failure ("cannot write PATH: reason"), empty when saved or nothing was due. A
  // failure is returned once, not at every later save that fails the same way (a read-only config folder
  // would otherwise fill the log and the window's list of failed writes); a save that works, or fails
  // differently, ends that silence.
  std::string saveIfDue();
  // The last save, at the end of the run; returns the failure (once, as above), empty when saved.
  std::string close();

 private:
  std::string save();

  std::string iniPath_;
  std::string lastFailure_;  // the failure already returned, until a save works
  bool closed_ = false;
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
