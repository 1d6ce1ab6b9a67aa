// The heatmap legend over the render: what the colours mean, the colour range (FrameStats::heatmap) with
// the controls that lock it, the pixel counts (no path / no value), why a view shows nothing, and the hover
// readout of the pixel under the mouse.
#pragma once

#include "renderer/frame_stats.h"
#include "renderer/settings/settings.h"
#include "ui/label_placement.h"

namespace raylab {

// In `box` (heatmapLegendBox), wrapping its text and scrolling what does not fit; false when no heatmap is
// chosen and nothing is drawn. Writes only Settings::heatmapRange (lock, min, max), clamped to the limits.
bool drawHeatmapLegend(Settings& settings, const FrameStats& stats, const Box& box);

// One line on what a view shows, for the legend and the help.
const char* heatmapDescription(HeatmapView view, HeatmapKeyColour keyColour);

}  // namespace raylab
