// All panels of the lab window, drawn in one call per frame, and what they remember between frames
// (timing history, the speed-accuracy book and its baseline run, the panels' layout, the last FrameStats).
#pragma once

#include <nlohmann/json.hpp>

#include "renderer/frame_stats.h"
#include "renderer/settings/settings.h"
#include "ui/baseline_run.h"
#include "ui/panel_layout.h"
#include "ui/speed_accuracy_book.h"
#include "ui/speed_accuracy_panel.h"
#include "ui/timing_history.h"
#include "ui/ui_state.h"

namespace raylab {

class LabUi {
 public:
  // Draws every panel between ImGui::NewFrame and ImGui::Render: edits `settings` and `view`, and
  // returns what the window must do.
  UiRequests draw(Settings& settings, ViewOptions& view, const CameraModel& camera);
  // Feeds a finished frame's statistics (and the settings it was rendered with) to the plots.
  void onFrame(const Settings& settings, const FrameStats& stats);
  const FrameStats& lastStats() const { return last_; }
  // Where the panels were drawn this frame, for the window screenshot's sidecar (panel_layout.h).
  nlohmann::json panelRects() const { return panelRectsJson(layout_.rects(), displayWidth_, displayHeight_); }

 private:
  TimingHistory timing_;
  SpeedAccuracyBook book_;
  BaselineRun baselines_;
  SpeedAccuracyView speedView_;
  PanelLayout layout_;
  float displayWidth_ = 0, displayHeight_ = 0;
  FrameStats last_;
};

}  // namespace raylab
