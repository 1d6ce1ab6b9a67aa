// Where the labels of a scatter plot go so that none overlaps another label or a marker and all stay inside
// the plot: each label tries the eight places around its marker, then the same farther out (drawn with a
// leader line back to the marker). Plain C++ (tests/cpu/test_panel_layout.cpp); scatter_plot draws it.
#pragma once

#include <vector>

namespace raylab {

struct Box {
  float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool overlaps(const Box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
  bool inside(const Box& o) const { return x0 >= o.x0 && y0 >= o.y0 && x1 <= o.x1 && y1 <= o.y1; }
};

struct LabelRequest {
  float x = 0, y = 0;           // the marker's centre
  float width = 0, height = 0;  // the label's size
};

struct LabelPlacement {
  Box box;              // where the label goes
  bool leader = false;  // away from its marker: draw a line to it
};

// In request order; earlier labels get the nearer places. Where no free place exists (more labels than the
// plot holds) a label takes the place that overlaps least.
std::vector<LabelPlacement> placeLabels(const std::vector<LabelRequest>& labels, const Box& area, float markerRadius);

}  // namespace raylab
