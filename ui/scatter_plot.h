// A small labelled scatter plot drawn with the ImGui draw list (ImPlot is not packaged): axes from zero
// to the largest value, one dot and label per point, the highlighted one larger.
#pragma once

#include <string>
#include <vector>

namespace raylab {

struct ScatterPoint {
  double x = 0.0, y = 0.0;
  std::string label;
  bool highlight = false;
};

void drawScatter(const char* id, const std::vector<ScatterPoint>& points, const char* xLabel, const char* yLabel,
                 double yMax, float height);  // yMax <= 0: from the data

}  // namespace raylab
