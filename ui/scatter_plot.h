// A small scatter plot drawn with the ImGui draw list (ImPlot is not packaged): each axis spans its data
// with a margin (never below zero), so close points stay apart; one marker and a short tag per point (label_placement.h keeps tags apart and inside the
// plot, with a leader line where one had to move away), vertical reference lines for baselines, and a strip
// under the axis for points that have no value on the y axis. Everything stays inside the widget's box.
#pragma once

#include <string>
#include <vector>

namespace raylab {

struct ScatterPoint {
  double x = 0.0;
  double y = -1.0;      // < 0: no value on this axis (drawn in the strip under the plot)
  std::string tag;      // drawn beside the marker: short ("3")
  std::string tooltip;  // shown on hover: the whole description
  bool highlight = false;
};

struct ReferenceLine {
  double x = 0.0;
  std::string tag;  // drawn at its top ("unsorted")
};

struct ScatterAxes {
  std::string x, y;     // titles
  std::string noValue;  // what the strip under the plot ("n/a") means, on hover: "no prediction"
};

// `empty`: a sentence drawn over the plot (wrapped), e.g. why no point has a value on the y axis; "" for none.
void drawScatter(const char* id, const std::vector<ScatterPoint>& points, const std::vector<ReferenceLine>& lines,
                 const ScatterAxes& axes, float height, const std::string& empty = "");

}  // namespace raylab
