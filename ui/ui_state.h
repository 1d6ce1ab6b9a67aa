// What the panels share besides Settings (which they edit) and FrameStats (which they read): options of
// the view that never reach the renderer, what the camera/scene panel shows, and the requests panels make
// of the window, which the window carries out after drawing (load a scene, jump to a viewpoint, ...).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace raylab {

struct ViewOptions {
  float resolutionScale = 1.0f;  // render size = window size * scale
  float defaultScale = 1.0f;     // what "reset to defaults" restores (the window lowers it on CPU devices)
  bool detailedStats = true;     // per-bounce readbacks: virtual warp efficiency, prediction accuracy
  bool showPanels = true;        // Tab hides them to look at the render alone
  bool showHelp = false;         // F1
  bool resetLayout = false;      // "Reset layout" (or a script): the panels go back to their default places
  // Why the device cannot run the rt tracer / SER (empty: it can); the window fills them from its device,
  // the method panel greys the options out with the reason.
  std::string rtUnavailable;
  // Set by the window where one stage of a frame is dearer than its render budget (the Timing panel says
  // so: the UI cannot turn faster than that stage); empty where every stage fits.
  std::string slowStageNote;
  // The window's own frame time (each UI frame: input, panels, the render work it runs), a running mean the
  // window keeps; 0 before the first. The Timing panel shows it as the UI's frame rate.
  float uiFrameMs = 0.0f;
  std::string serUnavailable;
  static constexpr float kMinScale = 0.05f;
  static constexpr float kMaxScale = 2.0f;
};

// The camera path section of the camera/scene panel (issue 37): what plays and what is being recorded.
struct CameraPathModel {
  std::string spec;          // what Play plays: --camera-path, or the last path recorded; empty: none yet
  bool playing = false;
  uint32_t frame = 0, frames = 0;  // while playing: the path frame being rendered, of how many
  bool recording = false;
  uint32_t recordedFrames = 0;     // keyframes recorded so far (one per UI frame)
  std::string status;        // what the last recording saved or why it failed, why a path did not play
};

// Shown by the camera/scene panel; the window fills it every frame.
struct CameraModel {
  std::string scene;
  std::vector<std::string> builtinScenes;
  std::vector<std::string> viewpoints;
  std::string cameraText;  // cameraToText of the current camera: exact, what "Copy camera" copies
  std::string cameraShortText;  // cameraToShortText: rounded, what the panel shows
  bool orbit = false;
  float speed = 1.0f;      // scene units per second
  std::string sceneError;  // last scene load failure
  std::vector<std::string> loadWarnings;  // what the loader skipped in the current scene (textures, ...)
  std::string cameraError; // last pasted camera that did not parse
  std::string screenshotDir;
  std::string lastScreenshot;  // what the last screenshot wrote, or why it failed
  std::vector<std::string> writeFailures;  // every file the window could not write (shots, imgui.ini, frame log)
  std::string deviceName;
  CameraPathModel path;
};

struct UiRequests {
  std::optional<std::string> loadScene;    // built-in name or glTF path
  std::optional<std::string> view;         // named viewpoint
  std::optional<std::string> cameraText;   // pasted or typed camera
  std::optional<bool> orbit;
  std::optional<float> speed;
  bool screenshotRender = false;
  bool screenshotWindow = false;
  bool togglePathPlayback = false;  // Play / Stop (the P key)
  bool togglePathRecording = false; // Record / Stop and save (the K key)
  bool resetLayout = false;  // the panels go back to their default places (LabUi does it, next frame)
  bool redrawPanels = false; // a panel was moved inside the window after it was drawn: draw them again
};

}  // namespace raylab
