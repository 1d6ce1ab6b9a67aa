#include "app/window/lab_window.h"

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>

#include <GLFW/glfw3.h>
#include <imgui.h>

#include "app/setting_flags.h"
#include "app/window/frame_log.h"
#include "app/window/lab_input.h"
#include "app/window/heatmap_hover.h"
#include "app/window/live_render.h"
#include "app/window/wall_clock.h"
#include "app/window/presenter.h"
#include "app/window/swapchain.h"
#include "renderer/heatmap/heatmap_rules.h"
#include "renderer/path_tracer.h"
#include "renderer/rt_tracer.h"
#include "renderer/vk/vk_context.h"
#include "scenes/scene_library.h"

namespace raylab {
namespace {

constexpr int kDefaultWidth = 1280, kDefaultHeight = 720;

// Ctrl+C or a polite kill closes the window as its close button would, so imgui.ini is still written.
volatile std::sig_atomic_t stopRequested = 0;
void requestStop(int) { stopRequested = 1; }

// Fly speed: a quarter of the scene's diagonal per second crosses any scene in a few seconds.
float speedFor(const Scene& scene) {
  float diagonal = glm::length(scene.bounds().extent());
  return diagonal > 0.0f ? 0.25f * diagonal : 1.0f;
}

}  // namespace

LabWindow::LabWindow(const WindowOptions& options)
    : options_(options), imgui_(options.iniPath, !options.reset, &ini_) {
  chooseStartSettings();
  loadStartScene();
  if (options_.sidecar && options_.sidecar->camera) scene_.view = *options_.sidecar->camera;
  if (!options_.cameraPath.empty()) {
    // A bad path is a usage error (exit 2) before any window opens. The tracer starts at the path's first
    // camera, as render's replay does (the key grid, when clamped to the camera, starts there too).
    pathPlayer_.play(pathRenderFor(options_.cameraPath, scene_.scene, std::nullopt));
    pathScene_ = settings_.scene;
    cameraModel_.path.spec = options_.cameraPath;
    scene_.view = cameraAt(pathPlayer_.path().path, 0, pathPlayer_.path().up).view;
  }
  if (!options_.script.empty()) script_.emplace(loadScript(options_.script));
  if (!options_.frameLog.empty()) frameLog_ = std::make_unique<FrameLog>(options_.frameLog);
  openWindow();
}

LabWindow::~LabWindow() {
  if (ctx_) vkDeviceWaitIdle(ctx_->device());
  tracer_.reset();
  live_.reset();
  presenter_.reset();
  layer_.reset();
  input_.reset();
  swapchain_.reset();
  if (surface_) vkDestroySurfaceKHR(ctx_->instance(), surface_, nullptr);
  window_.reset();
  ctx_.reset();
}

// Defaults < what imgui.ini remembers < --settings FILE < flags on the command line.
void LabWindow::chooseStartSettings() {
  Settings base = ini_.loadedSettings.value_or(Settings{});
  if (options_.sidecar) base = options_.sidecar->settings;
  settings_ = overlaySettingFlags(base, options_.renderArgs, /*skipUnknown=*/true);
  if (ini_.loadedScale) view_.resolutionScale = *ini_.loadedScale;
  if (ini_.loadedDetailed) view_.detailedStats = *ini_.loadedDetailed;
  ini_.settings = &settings_;
  ini_.view = &view_;
}

// A scene named on the command line (or in --settings) must load; one remembered in imgui.ini may have
// gone away since, and then the lab opens the default scene and says why in the scene panel.
void LabWindow::loadStartScene() {
  bool named = options_.sidecar || std::find(options_.renderArgs.begin(), options_.renderArgs.end(), "--scene") !=
                                       options_.renderArgs.end();
  try {
    scene_ = loadSceneForSettings(settings_);
  } catch (const std::exception& e) {
    if (named || settings_.scene == Settings{}.scene) throw;
    cameraModel_.sceneError = "remembered scene " + settings_.scene + ": " + e.what();
    std::fprintf(stderr, "raylab: %s; opening %s\n", cameraModel_.sceneError.c_str(), Settings{}.scene.c_str());
    settings_.scene = Settings{}.scene;
    settings_.view.clear();
    scene_ = loadSceneForSettings(settings_);
  }
}

void LabWindow::openWindow() {
  ContextOptions contextOptions = contextOptionsFor(options_.common);
  contextOptions.instanceExtensions = GlfwLibrary::requiredInstanceExtensions();
  contextOptions.deviceExtensions = {VK_KHR_SWAPCHAIN_EXTENSION_NAME};
  ctx_ = std::make_unique<VulkanContext>(contextOptions);
  // A CPU device (lavapipe) renders a quarter of the width and height by default: at 1280x720 that is
  // 320x180, about a frame per second on two cores, where the full size would take ten or more.
  view_.defaultScale = ctx_->info().isCpu ? 0.25f : 1.0f;
  {
    Settings rt = settings_, ser = settings_;
    rt.tracer = ser.tracer = Tracer::Rt;
    rt.ser = Ser::Off;
    ser.ser = Ser::On;
    view_.rtUnavailable = unsupportedSettings(ctx_->info(), rt);
    view_.serUnavailable = unsupportedSettings(ctx_->info(), ser);
  }
  if (std::string why = unsupportedSettings(ctx_->info(), settings_); !why.empty()) throw UsageError(why);
  if (!ini_.loadedScale) view_.resolutionScale = view_.defaultScale;
  if (options_.scale) view_.resolutionScale = *options_.scale;

  int width = options_.width > 0 ? options_.width : ini_.loadedWidth > 0 ? ini_.loadedWidth : kDefaultWidth;
  int height = options_.height > 0 ? options_.height : ini_.loadedHeight > 0 ? ini_.loadedHeight : kDefaultHeight;
  std::string title = "raylab - " + ctx_->info().name;
  window_ = std::make_unique<GlfwWindow>(width, height, title.c_str());
  surface_ = window_->createSurface(ctx_->instance(), ctx_->physicalDevice(), ctx_->queueFamily());
  swapchain_ = std::make_unique<Swapchain>(*ctx_, surface_);
  int fbw = 0, fbh = 0;
  window_->framebufferSize(&fbw, &fbh);
  swapchain_->recreate(static_cast<uint32_t>(fbw), static_cast<uint32_t>(fbh));
  framebufferWidth_ = fbw, framebufferHeight_ = fbh;
  input_ = std::make_unique<LabInput>(window_->handle());
  layer_ = std::make_unique<ImGuiLayer>(*ctx_, window_->handle(), *swapchain_);
  presenter_ = std::make_unique<Presenter>(*ctx_, *swapchain_, *layer_);
  live_ = std::make_unique<LiveRender>(*ctx_, options_.renderBudgetMs);

  resetCamera(scene_.view);
  syncTracer();
  // The first UI frame previews: the window shows the scene at once, and the preview tracer's pipelines
  // are built now rather than at the first camera move (their first build took ~0.5 s on lavapipe).
  live_->restarted();
  cameraModel_.builtinScenes = builtinSceneNames();
  cameraModel_.screenshotDir = options_.screenshotDir;
  cameraModel_.deviceName = ctx_->info().name + " (" + ctx_->info().driver + ")";
}

void LabWindow::recreateSwapchain() {
  vkDeviceWaitIdle(ctx_->device());
  int fbw = 0, fbh = 0;
  window_->framebufferSize(&fbw, &fbh);
  swapchain_->recreate(static_cast<uint32_t>(fbw), static_cast<uint32_t>(fbh));
  framebufferWidth_ = fbw, framebufferHeight_ = fbh;
  layer_->onSwapchainRecreated(*swapchain_);
  presenter_->onSwapchainRecreated();
  recreate_ = false;
}

int LabWindow::run() {
  lastFrame_ = std::chrono::steady_clock::now();
  auto started = lastFrame_;
  auto oldInt = std::signal(SIGINT, requestStop), oldTerm = std::signal(SIGTERM, requestStop);
  while (!stopRequested && frame()) {
  }
  finishRecording();  // a recording still running when the window closes is saved, not lost
  std::signal(SIGINT, oldInt);
  std::signal(SIGTERM, oldTerm);
  loopMsTotal_ = msSince(started);
  vkDeviceWaitIdle(ctx_->device());
  printSummary();
  if (std::string failure = imgui_.close(); !failure.empty()) reportWriteFailure(failure);
  try {
    if (frameLog_) frameLog_->close();
  } catch (const WriteError& e) {
    reportWriteFailure(e.what());
  }
  if (ctx_->validationErrors() > 0) {
    std::fprintf(stderr, "raylab: %u validation errors\n", ctx_->validationErrors());
    return kExitValidation;
  }
  if (!cameraModel_.writeFailures.empty()) {
    std::fprintf(stderr, "raylab: %zu writes failed (see above)\n", cameraModel_.writeFailures.size());
    return kExitFailure;
  }
  return kExitOk;
}

// One turn of the loop; false ends it. Minimised, it waits for events instead of rendering.
bool LabWindow::frame() {
  const auto start = std::chrono::steady_clock::now();
  const Settings before = settings_;
  glfwPollEvents();
  if (window_->shouldClose() || quit_) return false;
  if (window_->minimized()) {
    glfwWaitEventsTimeout(0.1);
    lastFrame_ = std::chrono::steady_clock::now();
    return true;
  }
  if (script_ && !runScript()) return false;
  int fbw = 0, fbh = 0;
  window_->framebufferSize(&fbw, &fbh);
  if (recreate_ || fbw != framebufferWidth_ || fbh != framebufferHeight_) recreateSwapchain();

  const auto now = std::chrono::steady_clock::now();
  float seconds = std::min(std::chrono::duration<float>(now - lastFrame_).count(), 0.25f);
  lastFrame_ = now;
  const bool drawPanels = panelsDue(now, before);
  panelsDirty_ = false;
  const auto panelsStart = std::chrono::steady_clock::now();
  const bool panelsDirtyNext = drawPanels && buildPanels();
  updateCamera(seconds);
  bool changed = false;
  const bool restarted = syncTracer(&changed);
  if (restarted) live_->restarted();
  updateHeatmapHover(*tracer_, heatmapShown(settings_) != HeatmapView::None);

  // This UI frame's share of the render (frame steps or a preview), then the panels over what is shown. A
  // window screenshot waits for a UI frame that completed a render frame, so it shows that frame.
  // A UI frame that presents spends the panels' time and a present besides its steps: the steps get less.
  const RenderTurn turn = live_->turn(*tracer_, scene_.scene, drawPanels ? msSince(panelsStart) + presentMs_ : 0.0);
  // A restart or preview changes what the panels show: they are rebuilt next UI frame. A completed frame's
  // image and statistics are shown by the next refresh.
  panelsDirty_ = panelsDirtyNext || restarted || turn.preview;
  imagePending_ = imagePending_ || turn.frameDone;
  const PresentedFrame shown = presentIfDue(drawPanels, turn, now);
  ++uiFrames_;
  // A running mean (one UI frame's time jumps with the render steps it ran) for the Timing panel.
  const float uiMs = float(msSince(start));
  view_.uiFrameMs = view_.uiFrameMs > 0.0f ? 0.9f * view_.uiFrameMs + 0.1f * uiMs : uiMs;
  if (frameLog_) logUiFrame(msSince(start), drawPanels, shown, changed, restarted, turn);
  if (!turn.frameDone) return true;
  noteSlowStep();
  // Statistics, screenshots and the script's frame count follow whole render frames only.
  ui_.onFrame(tracer_->settings(), *turn.frameDone);
  onPathFrameDone();
  learned_.onFrame(tracer_.get(), tracer_->accumulatedFrames(), tracer_->keyStage().cacheEpoch());
  ++frames_;
  wallMsTotal_ += turn.frameDone->wallMs;
  saveScreenshots(shown);
  if (script_) script_->frameDone();
  return true;
}

// The panels are rebuilt and the window presented only when something on it may have changed: input
// within the last kPanelSettleSeconds (ImGui's hover delays and animations play out in it), a script or
// panel change of settings, a preview or restart in the last UI frame, or completed render frames not yet
// shown, at most every kImageRefreshSeconds. Other UI frames only render their steps: on lavapipe a
// presented window costs tens of milliseconds whether or not the panels are rebuilt (docs/lab-window.md),
// which the UI frames of a live render cannot afford each time.
bool LabWindow::panelsDue(std::chrono::steady_clock::time_point now, const Settings& before) {
  if (input_->takeActivity()) lastInput_ = now;
  const bool refresh = imagePending_ && std::chrono::duration<double>(now - lastPresent_).count() >= kImageRefreshSeconds;
  // A pending window screenshot draws the panels every UI frame, so the shot shows them as they are now.
  return panelsDirty_ || refresh || !(settings_ == before) || !pendingWindowShot_.empty() ||
         std::chrono::duration<double>(now - lastInput_).count() < kPanelSettleSeconds;
}

// Builds this UI frame's panels and carries out what they asked; true when they must be built again next
// UI frame (a correction shows in the next build).
bool LabWindow::buildPanels() {
  layer_->newFrame();
  handleHotkeys();
  fillCameraModel();
  UiRequests requests = ui_.draw(settings_, view_, cameraModel_);
  ImGui::Render();
  if (std::string failure = imgui_.saveIfDue(); !failure.empty()) reportWriteFailure(failure);
  handleRequests(requests);
  return requests.redrawPanels;
}

// Draws and presents the window when the panels were built, a preview was rendered or a window screenshot
// is due with this completed frame; otherwise presents nothing.
PresentedFrame LabWindow::presentIfDue(bool drawPanels, const RenderTurn& turn,
                                       std::chrono::steady_clock::time_point now) {
  const bool capture = turn.frameDone && !pendingWindowShot_.empty();
  if (!drawPanels && !turn.preview && !capture) return {};
  const auto presentStart = std::chrono::steady_clock::now();
  PresentedFrame shown = presenter_->drawFrame(live_->shown(*tracer_), ImGui::GetDrawData(), capture,
                                               heatmapShown(settings_) != HeatmapView::None);
  presentMs_ += 0.5 * (msSince(presentStart) - presentMs_);  // smoothed: one slow present does not starve the steps
  recreate_ = shown.recreateSwapchain;
  panelsDirty_ = panelsDirty_ || recreate_;
  lastPresent_ = now;
  imagePending_ = imagePending_ && !drawPanels;  // a preview alone leaves the render's frame unshown
  return shown;
}

// One line of the frame log; a failed write is reported and ends the log, not the lab.
void LabWindow::logUiFrame(double uiMs, bool drawPanels, const PresentedFrame& shown, bool changed, bool restarted,
                           const RenderTurn& turn) {
  UiFrameRecord r;
  r.uiMs = uiMs;
  r.panels = drawPanels;
  r.presented = shown.rendered;
  r.changed = changed;
  r.restarted = restarted;
  r.framePaths = tracer_->framePaths();
  try {
    frameLog_->write(r, turn, tracer_->settings());
  } catch (const WriteError& e) {
    reportWriteFailure(std::string(e.what()) + " (the frame log stops here)");
    frameLog_.reset();
  }
}

// The render is the window's size times the resolution scale; the renderer restarts only what must.
bool LabWindow::syncTracer(bool* changedOut) {
  const VkExtent2D extent = swapchain_->extent();
  Settings want = settings_;
  auto scaled = [&](uint32_t size) {
    long v = std::lround(size * double(view_.resolutionScale));
    return static_cast<uint32_t>(std::clamp<long>(v, 1, SettingLimits::kMaxSize));
  };
  want.width = scaled(extent.width);
  want.height = scaled(extent.height);
  settings_.width = want.width, settings_.height = want.height;
  bool changed = false;
  if (!tracer_) {
    tracer_ = std::make_unique<PathTracer>(*ctx_, scene_.scene, want, camera_.viewpoint());
    changed = true;
  } else {
    if (!(want == tracer_->settings())) tracer_->applySettings(want), changed = true;
    if (!sameCamera(camera_.viewpoint(), tracer_->camera())) tracer_->setCamera(camera_.viewpoint()), changed = true;
  }
  tracer_->setDetailedStats(view_.detailedStats);
  if (changedOut) *changedOut = changed;
  int w = 0, h = 0;
  window_->windowSize(&w, &h);
  ini_.width = w, ini_.height = h;
  return changed && tracer_->accumulatedFrames() == 0;  // a change that kept the image needs no preview
}

// The Timing panel's line where one step of the frame is dearer than the whole render budget: the UI frame
// that renders it waits for it, so the UI cannot keep its rate there.
void LabWindow::noteSlowStep() {
  const StepTime& slow = live_->slowestStep();
  view_.slowStageNote.clear();
  if (slow.ms <= live_->budgetMs()) return;
  char text[200];
  std::snprintf(text, sizeof(text),
                "%s%s%s takes %.0f ms, more than the %.0f ms render budget: the UI waits for it (%.1f Hz then)",
                slow.name.c_str(), slow.bounce >= 0 ? " of bounce " : "",
                slow.bounce >= 0 ? std::to_string(slow.bounce).c_str() : "", slow.ms, live_->budgetMs(),
                1000.0 / slow.ms);
  view_.slowStageNote = text;
}

void LabWindow::updateCamera(float seconds) {
  const CameraInput in = input_->cameraInput(seconds);  // taken while a path plays too: no backlog after it
  if (!pathPlayer_.playing()) camera_.update(in);
  stepCameraPath();
}

void LabWindow::fillCameraModel() {
  cameraModel_.scene = settings_.scene;
  if (cameraModel_.loadWarnings.size() != scene_.scene.loadWarnings.size())
    cameraModel_.loadWarnings = scene_.scene.loadWarnings;
  cameraModel_.viewpoints.clear();
  for (const Viewpoint& v : scene_.scene.viewpoints) cameraModel_.viewpoints.push_back(v.name);
  cameraModel_.cameraText = cameraToText(camera_.viewpoint());
  cameraModel_.cameraShortText = cameraToShortText(camera_.viewpoint());
  cameraModel_.orbit = camera_.orbit();
  cameraModel_.speed = camera_.speed();
  fillCameraPathModel();
}

void LabWindow::resetCamera(const Viewpoint& view) {
  bool orbit = camera_.orbit();
  camera_.reset(view, speedFor(scene_.scene));
  if (orbit) camera_.setOrbit(true, view.target);
}

void LabWindow::printSummary() const {
  if (frames_ == 0 || uiFrames_ == 0) return;
  std::fprintf(stderr,
               "raylab: %llu render frames at %ux%u (render %ux%u): %.1f ms of render work each; %llu UI frames, "
               "%.1f ms per UI frame (%.1f fps)\n",
               static_cast<unsigned long long>(frames_), swapchain_->extent().width, swapchain_->extent().height,
               settings_.width, settings_.height, wallMsTotal_ / frames_, static_cast<unsigned long long>(uiFrames_),
               loopMsTotal_ / uiFrames_, 1000.0 * uiFrames_ / loopMsTotal_);
}

}  // namespace raylab

namespace raylab {

int runLabWindow(const WindowOptions& options) {
  LabWindow lab(options);
  return lab.run();
}

}  // namespace raylab
