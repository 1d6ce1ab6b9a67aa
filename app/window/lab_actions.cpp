// What the user, the panels and a script ask the lab window to do.
#include <cstdio>

#include <GLFW/glfw3.h>
#include <imgui.h>

#include "app/process_memory.h"
#include "app/setting_flags.h"
#include "app/window/lab_input.h"
#include "app/window/lab_window.h"
#include "app/window/presenter.h"
#include "app/window/script_keys.h"
#include "app/window/screenshot.h"
#include "app/window/swapchain.h"
#include "renderer/path_tracer.h"
#include "renderer/reorder/key_stage.h"
#include "renderer/settings/settings_table.h"
#include "renderer/vk/vk_context.h"

namespace raylab {

void LabWindow::handleHotkeys() {
  for (Hotkey key : input_->takeHotkeys()) {
    switch (key) {
      case Hotkey::Help: view_.showHelp = !view_.showHelp; break;
      case Hotkey::CloseHelp: view_.showHelp = false; break;
      case Hotkey::TogglePanels: view_.showPanels = !view_.showPanels; break;
      case Hotkey::ToggleOrbit: camera_.setOrbit(!camera_.orbit(), camera_.viewpoint().target); break;
      case Hotkey::ResetView: {
        const Viewpoint* named = scene_.scene.findViewpoint(settings_.view);
        resetCamera(named ? *named : scene_.view);  // scene_.view: the start camera (e.g. a sidecar's)
        break;
      }
      case Hotkey::ScreenshotRender: pendingRenderShot_ = freshScreenshotName(options_.screenshotDir, "render"); break;
      case Hotkey::ScreenshotWindow: pendingWindowShot_ = freshScreenshotName(options_.screenshotDir, "window"); break;
      case Hotkey::RestartLearning: tracer_->restartLearning(); break;
      case Hotkey::RecordPath: togglePathRecording(); break;
      case Hotkey::PlayPath: togglePathPlayback(); break;
    }
  }
}

void LabWindow::handleRequests(const UiRequests& r) {
  if (r.loadScene) loadScene(*r.loadScene, &cameraModel_.sceneError);
  if (r.view) gotoView(*r.view, &cameraModel_.sceneError);
  if (r.cameraText) {
    cameraModel_.cameraError.clear();
    applyCameraText(*r.cameraText, &cameraModel_.cameraError);
  }
  if (r.orbit) camera_.setOrbit(*r.orbit, camera_.viewpoint().target);
  if (r.speed) camera_.setSpeed(*r.speed);
  if (r.screenshotRender) pendingRenderShot_ = freshScreenshotName(options_.screenshotDir, "render");
  if (r.screenshotWindow) pendingWindowShot_ = freshScreenshotName(options_.screenshotDir, "window");
  if (r.togglePathPlayback) togglePathPlayback();
  if (r.togglePathRecording) togglePathRecording();
}

// Loads a scene and a renderer for it, or throws (SceneLoadError, UsageError, VulkanError) keeping the
// current ones.
void LabWindow::loadSceneOrThrow(const std::string& nameOrPath) {
  Settings next = settings_;
  next.scene = nameOrPath;
  next.view.clear();
  LoadedScene loaded = loadSceneForSettings(next);
  Settings start = tracer_->settings();
  // What the scene is made of comes from the settings asked for (a script's `set clutter-seed`, `set
  // wide-collapse`), not from the tracer of the old scene.
  for (const SettingRow& r : settingRows())
    if (r.effects & kEffectScene) r.copy(start, next);
  start.view = loaded.view.name;
  auto tracer = std::make_unique<PathTracer>(*ctx_, loaded.scene, start, loaded.view);
  vkDeviceWaitIdle(ctx_->device());
  tracer_ = std::move(tracer);
  live_->sceneChanged();
  live_->restarted();
  scene_ = std::move(loaded);
  settings_.scene = nameOrPath;
  settings_.view = scene_.view.name;
  resetCamera(scene_.view);
}

// The panel's way: on failure the lab keeps the current scene and says why in `error`.
bool LabWindow::loadScene(const std::string& nameOrPath, std::string* error) {
  try {
    loadSceneOrThrow(nameOrPath);
  } catch (const std::exception& e) {  // SceneLoadError, UsageError, VulkanError (e.g. out of memory)
    *error = e.what();  // loaders name the file themselves; say which scene otherwise
    if (error->find(nameOrPath) == std::string::npos) *error = nameOrPath + ": " + *error;
    return false;
  }
  error->clear();
  return true;
}

bool LabWindow::gotoView(const std::string& name, std::string* error) {
  const Viewpoint* v = scene_.scene.findViewpoint(name);
  if (!v) {
    *error = "no viewpoint '" + name + "' in " + scene_.scene.name + "; it has: " + scene_.scene.viewpointList();
    return false;
  }
  settings_.view = name;
  resetCamera(*v);
  return true;
}

bool LabWindow::applyCameraText(const std::string& text, std::string* error) {
  std::optional<Viewpoint> v = cameraFromText(text, camera_.viewpoint(), error);
  if (!v) return false;
  resetCamera(*v);
  return true;
}

// Runs the script's actions due now. A screenshot ends the turn: it is taken of the render frame completed
// next (several UI frames later when the frame renders in steps), and the script waits for it.
bool LabWindow::runScript() {
  if (!pendingRenderShot_.empty() || !pendingWindowShot_.empty()) return true;
  if (script_->finished()) return false;
  while (const ScriptAction* a = script_->next()) {
    try {
      runAction(*a);
    } catch (const SceneLoadError& e) {
      throw SceneLoadError(options_.script + ":" + std::to_string(a->line) + ": " + e.what());
    } catch (const std::exception& e) {
      throw ScriptError(options_.script + ":" + std::to_string(a->line) + ": " + e.what());
    }
    if (quit_) return false;
    if (a->kind == ScriptAction::Kind::Screenshot || a->kind == ScriptAction::Kind::ScreenshotWindow) break;
  }
  return true;
}

void LabWindow::runAction(const ScriptAction& a) {
  using K = ScriptAction::Kind;
  std::string error;
  switch (a.kind) {
    case K::Set:
      if (a.key == "scene") {
        loadSceneOrThrow(a.value);  // an unusable file exits 3, an unknown name 2, as on the command line
      } else if (a.key == "view") {
        if (!gotoView(a.value, &error)) throw ScriptError(error);
      } else if (a.key == "size") {
        Settings s;
        applySettingFlag(s, a.key, a.value);
        glfwSetWindowSize(window_->handle(), int(s.width), int(s.height));
      } else {
        applySettingFlag(settings_, a.key, a.value);
        // A setting the scene is made of (settings_table.h): the scene is built again.
        if (const SettingRow* row = findSettingRow(a.key); row && (row->effects & kEffectScene))
          loadSceneOrThrow(settings_.scene);
      }
      break;
    case K::Camera:
      if (!applyCameraText(a.value, &error)) throw ScriptError(error);
      break;
    case K::View:
      if (!gotoView(a.value, &error)) throw ScriptError(error);
      break;
    case K::Screenshot: pendingRenderShot_ = a.value; break;
    case K::ScreenshotWindow:
      if (!swapchain_->readable()) throw ScriptError("this surface cannot be read back (no TRANSFER_SRC usage)");
      pendingWindowShot_ = a.value;
      break;
    case K::ResetLayout: view_.resetLayout = true; break;
    case K::RestartLearning: tracer_->restartLearning(); break;
    case K::Memory:
      std::printf("%s\n", memoryReportLine(a.value, frames_, readProcessMemory()).c_str());
      std::fflush(stdout);
      break;
    case K::Press: pressScriptKey(*input_, a.value); break;
    case K::Quit: quit_ = true; break;
    case K::Wait: break;  // the runner counts the frames
  }
}

void LabWindow::saveScreenshots(const PresentedFrame& frame) {
  SidecarContent content;
  content.settings = tracer_->settings();
  content.settings.frames = tracer_->accumulatedFrames();  // a re-render with these settings matches the image
  content.camera = camera_.viewpoint();
  content.camera.name = settings_.view;
  content.stats = tracer_->stats();
  content.device = ctx_->info();
  content.learned = learned_.state(tracer_->keyStage().hasCache(), content.settings.frames, tracer_->keyStage().cacheEpoch());
  auto save = [&](std::string& name, const char* kind, const std::vector<uint32_t>& pixels, uint32_t w, uint32_t h) {
    if (name.empty()) return;
    content.kind = kind, content.imageWidth = w, content.imageHeight = h;
    content.panels = content.kind == std::string("window") ? ui_.panelRects() : nlohmann::json();
    try {
      std::string path = writeScreenshot(options_.screenshotDir, name, pixels, content);
      cameraModel_.lastScreenshot = "saved " + path;
      std::fprintf(stderr, "raylab: saved %s\n", path.c_str());
    } catch (const std::exception& e) {
      cameraModel_.lastScreenshot = std::string("screenshot failed: ") + e.what();
      reportWriteFailure(cameraModel_.lastScreenshot);
    }
    name.clear();
  };
  if (!pendingRenderShot_.empty()) save(pendingRenderShot_, "render", tracer_->readImage(), tracer_->width(), tracer_->height());
  if (!frame.window.empty()) save(pendingWindowShot_, "window", frame.window, frame.windowWidth, frame.windowHeight);
  if (!pendingWindowShot_.empty() && !swapchain_->readable()) {
    cameraModel_.lastScreenshot = "this window cannot be read back (the surface has no TRANSFER_SRC usage)";
    pendingWindowShot_.clear();
  }
}

void LabWindow::reportWriteFailure(const std::string& message) {
  std::fprintf(stderr, "raylab: %s\n", message.c_str());
  cameraModel_.writeFailures.push_back(message);
  panelsDirty_ = true;  // shown at once, not at the next input
}

}  // namespace raylab
