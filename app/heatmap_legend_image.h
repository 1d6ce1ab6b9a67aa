// The heatmap legend burned into saved heatmap PNGs (`raylab render --heatmap V --out x.png`, the window's
// F12 of a heatmap): a strip below the image with the colour bar, its min and max labels, the unit and
// scale, and the colours of "no path" and "no value" with their shares. Text by stb_easy_font (libstb-dev).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "renderer/heatmap/heatmap_stats.h"

namespace raylab {

struct LegendImage {
  std::vector<uint32_t> rgba;  // RGBA8, R in the low byte, rows top first
  uint32_t width = 0, height = 0;
};

// Layout of the strip, for drawing and for tests: the text scale (2 on images 640 wide or more), the strip's
// height, and the colour bar's rows and columns within it.
struct LegendLayout {
  uint32_t scale = 1;
  uint32_t height = 0;
  uint32_t barTop = 0, barBottom = 0;  // rows of the bar, relative to the strip
  uint32_t barLeft = 0, barRight = 0;  // columns [barLeft, barRight)
  uint32_t textTop = 0;                // the min / max row; the unit below, then a swatch a row
  static LegendLayout forWidth(uint32_t width);
};

// `image` with the legend strip of `h` appended below it (the heatmap's own pixels are untouched). An image
// without a heatmap (h.view empty) comes back as it is.
LegendImage withHeatmapLegend(const std::vector<uint32_t>& image, uint32_t width, uint32_t height, const HeatmapStats& h);

// "3 .. 120 traversal steps (linear, frame's range)": the legend as one line, for headless output.
std::string heatmapLegendLine(const HeatmapStats& h);

}  // namespace raylab
