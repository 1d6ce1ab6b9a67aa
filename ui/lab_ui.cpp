#include "ui/lab_ui.h"

#include <imgui.h>

#include "ui/camera_scene_panel.h"
#include "ui/heatmap_legend.h"
#include "ui/help_overlay.h"
#include "ui/method_panel.h"
#include "ui/speed_accuracy_panel.h"
#include "ui/timing_panel.h"

namespace raylab {

UiRequests LabUi::draw(Settings& settings, ViewOptions& view, const CameraModel& camera) {
  UiRequests requests;
  if (view.showPanels) {
    drawMethodPanel(settings, view);
    drawTimingPanel(timing_, last_, settings, view);
    drawSpeedAccuracyPanel(book_, settings);
    requests = drawCameraScenePanel(camera);
  }
  drawHeatmapLegend(settings, last_);
  drawHelpOverlay(&view.showHelp);
  return requests;
}

void LabUi::onFrame(const Settings& settings, const FrameStats& stats) {
  last_ = stats;
  timing_.push(stats);
  book_.record(settings, stats);
}

}  // namespace raylab
