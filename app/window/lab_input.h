// Keyboard and mouse for the lab: hotkey presses queued by a GLFW callback (a press between two slow
// frames is not lost), and held keys and mouse movement turned into CameraInput. Input that Dear ImGui is
// using (typing in a field, dragging a slider) does not move the camera.
#pragma once

#include <vector>

#include "app/fly_camera.h"

struct GLFWwindow;

namespace raylab {

enum class Hotkey { Help, ScreenshotRender, ScreenshotWindow, TogglePanels, ToggleOrbit, CloseHelp, ResetView, RestartLearning,
                    RecordPath, PlayPath };

class LabInput {
 public:
  // Must be constructed before the ImGui GLFW backend, which chains the callbacks installed here.
  explicit LabInput(GLFWwindow* window);
  std::vector<Hotkey> takeHotkeys();
  // A key press as the keyboard would deliver it (GLFW key and modifiers): a script's `press`.
  void press(int key, int mods);
  // Movement since the last call; `seconds` is the frame time movement scales with.
  CameraInput cameraInput(float seconds);
  // Whether any input arrived (keys, characters, mouse buttons, moves, scrolls, focus) since the last call:
  // the window rebuilds its panels only after input or when what they show changed.
  bool takeActivity();

 private:
  static void onKey(GLFWwindow* window, int key, int scancode, int action, int mods);
  static void onScroll(GLFWwindow* window, double dx, double dy);
  static void onMouseButton(GLFWwindow* window, int button, int action, int mods);
  static void onCursor(GLFWwindow* window, double x, double y);
  static void onChar(GLFWwindow* window, unsigned int c);
  static void onFocus(GLFWwindow* window, int focused);
  static void onEnter(GLFWwindow* window, int entered);

  GLFWwindow* window_;
  std::vector<Hotkey> hotkeys_;
  float scroll_ = 0.0f;
  bool looking_ = false;
  bool activity_ = true;  // the first frame draws
  double lastX_ = 0.0, lastY_ = 0.0;
};

}  // namespace raylab
