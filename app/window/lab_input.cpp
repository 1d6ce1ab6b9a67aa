#include "app/window/lab_input.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_internal.h>

namespace raylab {
namespace {

LabInput* self(GLFWwindow* window) { return static_cast<LabInput*>(glfwGetWindowUserPointer(window)); }

// Whether the pointer is over a window ImGui drew last: its WantCaptureMouse is a frame old, so a wheel turned
// as the pointer reached a panel dollied the camera (and restarted accumulation) instead of scrolling it.
bool overPanel(GLFWwindow* window) {
  if (!ImGui::GetCurrentContext()) return false;
  double x = 0.0, y = 0.0;
  glfwGetCursorPos(window, &x, &y);
  const ImVec2 p{float(x), float(y)};
  for (ImGuiWindow* w : ImGui::GetCurrentContext()->Windows)
    if (w->WasActive && !w->Hidden && !(w->Flags & ImGuiWindowFlags_ChildWindow) && w->Rect().Contains(p)) return true;
  return false;
}

}  // namespace

LabInput::LabInput(GLFWwindow* window) : window_(window) {
  glfwSetWindowUserPointer(window, this);
  glfwSetKeyCallback(window, onKey);
  glfwSetScrollCallback(window, onScroll);
  glfwSetMouseButtonCallback(window, onMouseButton);
  glfwSetCursorPosCallback(window, onCursor);
  glfwSetCharCallback(window, onChar);
  glfwSetWindowFocusCallback(window, onFocus);
  glfwSetCursorEnterCallback(window, onEnter);
}

bool LabInput::takeActivity() {
  const bool any = activity_;
  activity_ = false;
  return any;
}

void LabInput::onCursor(GLFWwindow* window, double, double) { self(window)->activity_ = true; }
void LabInput::onChar(GLFWwindow* window, unsigned int) { self(window)->activity_ = true; }
void LabInput::onFocus(GLFWwindow* window, int) { self(window)->activity_ = true; }
void LabInput::onEnter(GLFWwindow* window, int) { self(window)->activity_ = true; }

void LabInput::onKey(GLFWwindow* window, int key, int, int action, int mods) {
  LabInput* in = self(window);
  in->activity_ = true;
  if (action != GLFW_PRESS) return;
  // Function keys work even while a text field has focus; letters belong to the field then.
  const bool typing = ImGui::GetCurrentContext() && ImGui::GetIO().WantTextInput;
  switch (key) {
    case GLFW_KEY_F1: in->hotkeys_.push_back(Hotkey::Help); break;
    case GLFW_KEY_F12:
      in->hotkeys_.push_back(mods & GLFW_MOD_SHIFT ? Hotkey::ScreenshotWindow : Hotkey::ScreenshotRender);
      break;
    case GLFW_KEY_ESCAPE: in->hotkeys_.push_back(Hotkey::CloseHelp); break;
    case GLFW_KEY_TAB:
      if (!typing) in->hotkeys_.push_back(Hotkey::TogglePanels);
      break;
    case GLFW_KEY_O:
      if (!typing) in->hotkeys_.push_back(Hotkey::ToggleOrbit);
      break;
    case GLFW_KEY_R:  // back to the viewpoint after flying out of the scene
      if (!typing) in->hotkeys_.push_back(Hotkey::ResetView);
      break;
    case GLFW_KEY_L:  // a fresh length cache and accumulation: what a re-render of a screenshot learns
      if (!typing) in->hotkeys_.push_back(Hotkey::RestartLearning);
      break;
    case GLFW_KEY_K:  // record a camera path (keyframes), again to stop and save it
      if (!typing) in->hotkeys_.push_back(Hotkey::RecordPath);
      break;
    case GLFW_KEY_P:  // play the camera path, again to stop
      if (!typing) in->hotkeys_.push_back(Hotkey::PlayPath);
      break;
    default: break;
  }
}

void LabInput::onScroll(GLFWwindow* window, double, double dy) {
  self(window)->activity_ = true;
  if ((ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureMouse) || overPanel(window)) return;
  self(window)->scroll_ += static_cast<float>(dy);
}

// Looking starts only when the right button goes down over the render, not over a panel.
void LabInput::onMouseButton(GLFWwindow* window, int button, int action, int) {
  self(window)->activity_ = true;
  if (button != GLFW_MOUSE_BUTTON_RIGHT) return;
  LabInput* in = self(window);
  if (action == GLFW_PRESS && !(ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureMouse)) {
    in->looking_ = true;
    glfwGetCursorPos(window, &in->lastX_, &in->lastY_);
  } else if (action == GLFW_RELEASE) {
    in->looking_ = false;
  }
}

void LabInput::press(int key, int mods) { onKey(window_, key, 0, GLFW_PRESS, mods); }

std::vector<Hotkey> LabInput::takeHotkeys() {
  std::vector<Hotkey> out;
  out.swap(hotkeys_);
  return out;
}

CameraInput LabInput::cameraInput(float seconds) {
  CameraInput in;
  in.seconds = seconds;
  in.zoom = scroll_;
  scroll_ = 0.0f;
  if (looking_) {
    double x, y;
    glfwGetCursorPos(window_, &x, &y);
    in.look = {static_cast<float>(x - lastX_), static_cast<float>(y - lastY_)};
    lastX_ = x, lastY_ = y;
  }
  if (ImGui::GetIO().WantCaptureKeyboard) return in;
  auto held = [&](int key) { return glfwGetKey(window_, key) == GLFW_PRESS ? 1.0f : 0.0f; };
  in.move = {held(GLFW_KEY_D) - held(GLFW_KEY_A), held(GLFW_KEY_E) - held(GLFW_KEY_Q), held(GLFW_KEY_W) - held(GLFW_KEY_S)};
  in.fast = held(GLFW_KEY_LEFT_SHIFT) > 0 || held(GLFW_KEY_RIGHT_SHIFT) > 0;
  return in;
}

}  // namespace raylab
