#include "app/window/imgui_layer.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_vulkan.h>

#include "app/window/color_render_pass.h"
#include "app/window/imgui_vulkan_compat.h"
#include "app/window/swapchain.h"
#include "renderer/checked_write.h"
#include "renderer/vk/vk_check.h"
#include "renderer/vk/vk_context.h"
#include "ui/settings_ini.h"

namespace raylab {
namespace {

void checkVk(VkResult r) {
  if (r < 0) throw VulkanError("Dear ImGui's Vulkan backend: " + vkResultName(r));
}

}  // namespace

ImGuiSession::ImGuiSession(const std::string& iniPath, bool load, IniState* ini) : iniPath_(iniPath) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::StyleColorsDark();
  ImGui::GetIO().IniFilename = nullptr;  // ImGui's own saves are unchecked: save() writes the file
  if (!iniPath_.empty()) {  // the config folder may be new
    std::error_code error;
    std::filesystem::create_directories(std::filesystem::path(iniPath_).parent_path(), error);
  }
  installIniHandler(ini);
  // Reading now marks the settings loaded, so ImGui does not read them again at the first frame;
  // with --reset an empty text does the same and the file is overwritten on exit.
  if (load && !iniPath_.empty()) ImGui::LoadIniSettingsFromDisk(iniPath_.c_str());
  else ImGui::LoadIniSettingsFromMemory("");
}

// The last save runs the lab's handler too, so its IniState must still be alive here.
ImGuiSession::~ImGuiSession() {
  if (!closed_)
    if (std::string failure = save(); !failure.empty()) std::fprintf(stderr, "raylab: %s\n", failure.c_str());
  ImGui::DestroyContext();
}

std::string ImGuiSession::save() {
  size_t size = 0;
  const char* text = ImGui::SaveIniSettingsToMemory(&size);  // also clears io.WantSaveIniSettings
  if (iniPath_.empty()) return "";
  try {
    writeFileChecked(iniPath_, std::string_view(text, size));
  } catch (const WriteError& e) {
    if (lastFailure_ == e.what()) return "";
    return lastFailure_ = e.what();
  }
  lastFailure_.clear();
  return "";
}

std::string ImGuiSession::saveIfDue() { return ImGui::GetIO().WantSaveIniSettings ? save() : ""; }

std::string ImGuiSession::close() {
  closed_ = true;
  return save();
}

ImGuiLayer::ImGuiLayer(const VulkanContext& ctx, GLFWwindow* window, const Swapchain& swapchain) : ctx_(ctx) {
  VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 16};
  VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  poolInfo.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
  poolInfo.maxSets = 16;
  poolInfo.poolSizeCount = 1;
  poolInfo.pPoolSizes = &size;
  VK_CHECK(vkCreateDescriptorPool(ctx.device(), &poolInfo, nullptr, &pool_));
  createRenderPass(swapchain.format());
  createFramebuffers(swapchain);

  ImGui_ImplGlfw_InitForVulkan(window, true);
  ImGui_ImplVulkan_InitInfo info{};
  info.Instance = ctx.instance();
  info.PhysicalDevice = ctx.physicalDevice();
  info.Device = ctx.device();
  info.QueueFamily = ctx.queueFamily();
  info.Queue = ctx.queue();
  info.DescriptorPool = pool_;
  info.MinImageCount = swapchain.minImageCount();
  info.ImageCount = std::max(swapchain.imageCount(), swapchain.minImageCount());
  info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
  info.CheckVkResultFn = checkVk;
  ImGui_ImplVulkan_Init(&info, renderPass_);
  uploadImGuiFonts(ctx);
}

ImGuiLayer::~ImGuiLayer() {
  vkDeviceWaitIdle(ctx_.device());
  ImGui_ImplVulkan_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  destroyFramebuffers();
  vkDestroyRenderPass(ctx_.device(), renderPass_, nullptr);
  vkDestroyDescriptorPool(ctx_.device(), pool_, nullptr);
}

// One colour attachment that keeps what the blit wrote (LOAD) and stays ready for more transfers.
void ImGuiLayer::createRenderPass(VkFormat format) {
  renderPass_ = createColorRenderPass(ctx_.device(), {format, VK_ATTACHMENT_LOAD_OP_LOAD, VK_ATTACHMENT_STORE_OP_STORE,
                                                      VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                                      VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL});
}

void ImGuiLayer::createFramebuffers(const Swapchain& swapchain) {
  extent_ = swapchain.extent();
  for (uint32_t i = 0; i < swapchain.imageCount(); ++i) {
    VkImageView view = swapchain.view(i);
    VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    info.renderPass = renderPass_;
    info.attachmentCount = 1;
    info.pAttachments = &view;
    info.width = extent_.width;
    info.height = extent_.height;
    info.layers = 1;
    framebuffers_.push_back(VK_NULL_HANDLE);
    VK_CHECK(vkCreateFramebuffer(ctx_.device(), &info, nullptr, &framebuffers_.back()));
  }
}

void ImGuiLayer::destroyFramebuffers() {
  for (VkFramebuffer f : framebuffers_) vkDestroyFramebuffer(ctx_.device(), f, nullptr);
  framebuffers_.clear();
}

void ImGuiLayer::onSwapchainRecreated(const Swapchain& swapchain) {
  destroyFramebuffers();
  createFramebuffers(swapchain);
  ImGui_ImplVulkan_SetMinImageCount(swapchain.minImageCount());
}

void ImGuiLayer::newFrame() {
  ImGui_ImplVulkan_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
}

void ImGuiLayer::record(VkCommandBuffer cmd, uint32_t index, ImDrawData* data) {
  VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  begin.renderPass = renderPass_;
  begin.framebuffer = framebuffers_[index];
  begin.renderArea.extent = extent_;
  vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
  ImGui_ImplVulkan_RenderDrawData(data, cmd);
  vkCmdEndRenderPass(cmd);
}

}  // namespace raylab
