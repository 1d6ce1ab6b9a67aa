#include "app/window/glfw_window.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <cstdio>
#include <string>

#include "renderer/vk/vk_check.h"

namespace raylab {
namespace {

std::string glfwError() {
  const char* text = nullptr;
  glfwGetError(&text);
  return text ? text : "unknown GLFW error";
}

}  // namespace

GlfwLibrary::GlfwLibrary() {
  if (!glfwInit()) throw NoDisplayError("cannot open a window: " + glfwError());
  if (!glfwVulkanSupported()) {
    glfwTerminate();
    throw NoDisplayError("GLFW finds no Vulkan loader for windows");
  }
}

GlfwLibrary::~GlfwLibrary() { glfwTerminate(); }

std::vector<const char*> GlfwLibrary::requiredInstanceExtensions() {
  uint32_t count = 0;
  const char** names = glfwGetRequiredInstanceExtensions(&count);
  if (!names) throw NoDisplayError("GLFW cannot present with Vulkan here: " + glfwError());
  return std::vector<const char*>(names, names + count);
}

GlfwWindow::GlfwWindow(int width, int height, const char* title) {
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
  window_ = glfwCreateWindow(width, height, title, nullptr, nullptr);
  if (!window_) throw NoDisplayError("cannot create a window: " + glfwError());
}

GlfwWindow::~GlfwWindow() { glfwDestroyWindow(window_); }

VkSurfaceKHR GlfwWindow::createSurface(VkInstance instance, VkPhysicalDevice device, uint32_t queueFamily) const {
  VkSurfaceKHR surface = VK_NULL_HANDLE;
  VK_CHECK(glfwCreateWindowSurface(instance, window_, nullptr, &surface));
  VkBool32 supported = VK_FALSE;
  VK_CHECK(vkGetPhysicalDeviceSurfaceSupportKHR(device, queueFamily, surface, &supported));
  if (!supported) {
    vkDestroySurfaceKHR(instance, surface, nullptr);
    throw VulkanError("the device's compute queue cannot present to this window");
  }
  return surface;
}

void GlfwWindow::framebufferSize(int* width, int* height) const { glfwGetFramebufferSize(window_, width, height); }
void GlfwWindow::windowSize(int* width, int* height) const { glfwGetWindowSize(window_, width, height); }

bool GlfwWindow::minimized() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return w == 0 || h == 0 || glfwGetWindowAttrib(window_, GLFW_ICONIFIED);
}

bool GlfwWindow::shouldClose() const { return glfwWindowShouldClose(window_); }

}  // namespace raylab
