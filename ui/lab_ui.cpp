#include "ui/lab_ui.h"

#include <imgui.h>

#include "ui/camera_scene_panel.h"
#include "ui/clip_check.h"
#include "ui/heatmap_legend.h"
#include "ui/help_overlay.h"
#include "ui/method_panel.h"
#include "ui/panel_placement.h"
#include "ui/timing_panel.h"

namespace raylab {

UiRequests LabUi::draw(Settings& settings, ViewOptions& view, const CameraModel& camera) {
  UiRequests requests;
  baselines_.steer(settings);  // before the panels, so they show what will be rendered
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  displayWidth_ = display.x, displayHeight_ = display.y;
  const bool reset = view.resetLayout;
  view.resetLayout = false;
  if (reset) layout_.forget();
  layout_.startFrame();
  bool corrected = false;
  if (view.showPanels) {
    auto panel = [&](Panel p, auto&& drawPanel) {
      placeNextPanel(p, reset);
      startClipReport();
      drawPanel();
      corrected = keepPanelInside(p, layout_) || corrected;
      ClipReport clipped = finishClipReport(panelTitle(p));
      layout_.setClipping(clipped.hiddenWidth, std::move(clipped.items));
    };
    panel(Panel::Method, [&] { drawMethodPanel(settings, view); });
    panel(Panel::Timing, [&] { drawTimingPanel(timing_, last_, settings, view); });
    panel(Panel::SpeedAccuracy, [&] { drawSpeedAccuracyPanel(book_, baselines_, speedView_, settings); });
    panel(Panel::SceneCamera, [&] { requests = drawCameraScenePanel(camera); });
  }
  requests.redrawPanels = corrected;
  if (requests.resetLayout) view.resetLayout = true;
  startClipReport();
  if (drawHeatmapLegend(settings, last_, heatmapLegendBox(display.x, display.y))) {
    recordWindow(kHeatmapLegendTitle, layout_);
    ClipReport clipped = finishClipReport(kHeatmapLegendTitle);
    layout_.setClipping(clipped.hiddenWidth, std::move(clipped.items));
  }
  drawHelpOverlay(&view.showHelp);
  return requests;
}

void LabUi::onFrame(const Settings& settings, const FrameStats& stats) {
  last_ = stats;
  timing_.push(stats);
  baselines_.onFrame(settings);
  book_.record(settings, stats);
}

}  // namespace raylab
