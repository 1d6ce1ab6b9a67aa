// The speed-accuracy panel: one point per method and parameter set (speed_accuracy_book.h) on a scatter of
// cost (trace or frame time) against accuracy (the bench's prediction error, cell-hit rate) or warp
// efficiency, the unsorted and megakernel baselines as reference lines, and a table of every point (the
// plot's numbered legend). "Measure baselines" asks for those through Settings (baseline_run.h).
#pragma once

#include "renderer/settings/settings.h"
#include "ui/baseline_run.h"
#include "ui/speed_accuracy_book.h"

namespace raylab {

// The panel's own choices, kept between frames.
struct SpeedAccuracyView {
  int xAxis = 1;  // trace, frame (the default: the baselines compare there), trace + reorder
  int yAxis = 0;  // prediction error, cell-hit rate, warp efficiency
};

void drawSpeedAccuracyPanel(SpeedAccuracyBook& book, BaselineRun& baselines, SpeedAccuracyView& view,
                            Settings& settings);

}  // namespace raylab
