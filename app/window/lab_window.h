// The interactive lab: owns the window, the Vulkan objects that show the render, the path tracer and the
// panels, and runs the frame loop. lab_window.cpp builds it and runs frames; lab_actions.cpp carries out
// what the user, the panels and a script ask for (scenes, viewpoints, camera text, screenshots).
#pragma once

#include <chrono>
#include <memory>
#include <optional>
#include <string>

#include "app/camera_path/camera_path_recorder.h"
#include "app/fly_camera.h"
#include "app/learned_history.h"
#include "app/scene_setup.h"
#include "app/ui_script.h"
#include "app/window/glfw_window.h"
#include "app/window/imgui_layer.h"
#include "app/window/path_player.h"
#include "app/window/window_options.h"
#include "renderer/settings/settings.h"
#include "ui/lab_ui.h"
#include "ui/settings_ini.h"
#include "ui/ui_state.h"

namespace raylab {

class VulkanContext;
class Swapchain;
class Presenter;
class PathTracer;
class LabInput;
class FrameLog;
class LiveRender;
struct PresentedFrame;
struct RenderTurn;

class LabWindow {
 public:
  explicit LabWindow(const WindowOptions& options);
  ~LabWindow();
  // Runs until the window closes or the script ends; returns the exit code.
  int run();

 private:
  // lab_window.cpp
  void chooseStartSettings();
  void loadStartScene();
  void openWindow();
  bool frame();
  bool panelsDue(std::chrono::steady_clock::time_point now, const Settings& before);
  bool buildPanels();
  PresentedFrame presentIfDue(bool drawPanels, const RenderTurn& turn, std::chrono::steady_clock::time_point now);
  void logUiFrame(double uiMs, bool drawPanels, const PresentedFrame& shown, bool changed, bool restarted,
                  const RenderTurn& turn);
  void recreateSwapchain();
  // True when the render restarted its accumulation; `changed`: the settings or camera changed (a change
  // of strategy, grid, clamp or policy keeps accumulating, yet the frame log records it as a change).
  bool syncTracer(bool* changed = nullptr);
  void updateCamera(float seconds);
  void noteSlowStep();
  void fillCameraModel();
  void printSummary() const;

  // lab_actions.cpp
  void handleHotkeys();
  void handleRequests(const UiRequests& requests);
  bool runScript();  // false once the script has quit
  void runAction(const ScriptAction& action);
  bool loadScene(const std::string& nameOrPath, std::string* error);
  void loadSceneOrThrow(const std::string& nameOrPath);
  bool gotoView(const std::string& name, std::string* error);
  bool applyCameraText(const std::string& text, std::string* error);
  void saveScreenshots(const PresentedFrame& frame);
  // A file that could not be written: on stderr and in the scene panel; the window keeps running and
  // exits 1 at the end (nothing lost without a word).
  void reportWriteFailure(const std::string& message);
  void resetCamera(const Viewpoint& view);

  // lab_camera_path.cpp: playing and recording camera paths (issue 37)
  void stepCameraPath();
  void onPathFrameDone();
  void togglePathPlayback();
  void playCameraPath(const std::string& spec);
  void togglePathRecording();
  void finishRecording();
  void fillCameraPathModel();

  WindowOptions options_;
  // Declared before imgui_, so they outlive it: ImGui writes imgui.ini through ini_ while being destroyed.
  Settings settings_;
  ViewOptions view_;
  IniState ini_;
  GlfwLibrary glfw_;
  ImGuiSession imgui_;
  CameraModel cameraModel_;
  LabUi ui_;
  FlyCamera camera_;
  LoadedScene scene_;
  std::optional<ScriptRunner> script_;

  std::unique_ptr<VulkanContext> ctx_;
  std::unique_ptr<GlfwWindow> window_;
  VkSurfaceKHR surface_ = VK_NULL_HANDLE;
  std::unique_ptr<Swapchain> swapchain_;
  std::unique_ptr<LabInput> input_;
  std::unique_ptr<ImGuiLayer> layer_;
  std::unique_ptr<Presenter> presenter_;
  std::unique_ptr<PathTracer> tracer_;
  std::unique_ptr<LiveRender> live_;
  std::unique_ptr<FrameLog> frameLog_;

  bool quit_ = false;
  bool recreate_ = false;
  int framebufferWidth_ = 0, framebufferHeight_ = 0;  // what the swapchain was made for
  std::string pendingRenderShot_, pendingWindowShot_;  // names of screenshots due after this frame
  std::chrono::steady_clock::time_point lastFrame_, lastInput_, lastPresent_;
  static constexpr double kPanelSettleSeconds = 1.0, kImageRefreshSeconds = 0.1;
  bool panelsDirty_ = true;
  bool imagePending_ = false;
  double presentMs_ = 0.0;  // what presenting the window took, smoothed (LiveRender leaves it room)
  uint64_t frames_ = 0;
  LearnedHistory learned_;  // whether a screenshot's length cache learned over its frames only
  PathPlayer pathPlayer_;
  std::string pathScene_;       // the scene the playing path was resolved for (a new scene stops it)
  CameraPathRecorder recorder_;
  SidecarContent recording_;    // the recording's sidecar as of its last keyframe (settings, stats, device)
  uint64_t uiFrames_ = 0;
  double wallMsTotal_ = 0.0, loopMsTotal_ = 0.0;
};

}  // namespace raylab
