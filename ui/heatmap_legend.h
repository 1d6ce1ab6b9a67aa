// The colour legend of the heatmap that replaces the render: what the colours mean and the value range
// the renderer reports (FrameStats::heatmapMin/Max/Unit).
#pragma once

#include <glm/glm.hpp>

#include "renderer/frame_stats.h"
#include "renderer/settings.h"

namespace raylab {

void drawHeatmapLegend(const Settings& settings, const FrameStats& stats);

// The ramp drawn in the legend for scalar heatmaps (t in [0, 1]): Turbo, by its polynomial
// approximation, as shaders/heatmap_colorize.comp (keep the two in step so the legend reads the image).
glm::vec3 heatmapRamp(float t);

// One line on what a view shows, for the legend and the help.
const char* heatmapDescription(HeatmapView view);

}  // namespace raylab
