// All panels of the lab window, drawn in one call per frame, and what they remember between frames
// (timing history, each strategy's last speed-accuracy point, the last FrameStats).
#pragma once

#include "renderer/frame_stats.h"
#include "renderer/settings.h"
#include "ui/speed_accuracy_book.h"
#include "ui/timing_history.h"
#include "ui/ui_state.h"

namespace raylab {

class LabUi {
 public:
  // Draws every panel between ImGui::NewFrame and ImGui::Render: edits `settings` and `view`, and
  // returns what the window must do.
  UiRequests draw(Settings& settings, ViewOptions& view, const CameraModel& camera);
  // Feeds a finished frame's statistics to the plots.
  void onFrame(const Settings& settings, const FrameStats& stats);
  const FrameStats& lastStats() const { return last_; }

 private:
  TimingHistory timing_;
  SpeedAccuracyBook book_;
  FrameStats last_;
};

}  // namespace raylab
