// The timing panel: live per-stage GPU times (a scrolling history per stage and a stacked bar per bounce),
// SIMT and virtual warp efficiency, rays per second, frame time and memory. It reads FrameStats; the only
// Settings it writes is the SIMT counting switch, which belongs with the numbers it enables.
#pragma once

#include "renderer/frame_stats.h"
#include "renderer/settings/settings.h"
#include "ui/timing_history.h"
#include "ui/ui_state.h"

namespace raylab {

void drawTimingPanel(const TimingHistory& history, const FrameStats& stats, Settings& settings, ViewOptions& view);

}  // namespace raylab
