// GLFW, for the window alone: initialisation, a resizable window without a GL context, its Vulkan
// surface and the instance extensions that surface needs.
#pragma once

#include <stdexcept>
#include <vector>

#include <vulkan/vulkan.h>

struct GLFWwindow;

namespace raylab {

// There is no display to open a window on (no DISPLAY/WAYLAND_DISPLAY, or GLFW cannot reach it).
struct NoDisplayError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// glfwInit .. glfwTerminate. Throws NoDisplayError when GLFW cannot start or has no Vulkan loader.
class GlfwLibrary {
 public:
  GlfwLibrary();
  ~GlfwLibrary();
  GlfwLibrary(const GlfwLibrary&) = delete;
  GlfwLibrary& operator=(const GlfwLibrary&) = delete;
  static std::vector<const char*> requiredInstanceExtensions();
};

class GlfwWindow {
 public:
  GlfwWindow(int width, int height, const char* title);
  ~GlfwWindow();
  GlfwWindow(const GlfwWindow&) = delete;
  GlfwWindow& operator=(const GlfwWindow&) = delete;

  GLFWwindow* handle() const { return window_; }
  // Throws when the surface cannot be created or `queueFamily` cannot present to it.
  VkSurfaceKHR createSurface(VkInstance instance, VkPhysicalDevice device, uint32_t queueFamily) const;
  void framebufferSize(int* width, int* height) const;
  void windowSize(int* width, int* height) const;
  bool minimized() const;
  bool shouldClose() const;

 private:
  GLFWwindow* window_ = nullptr;
};

}  // namespace raylab
