// Where the lab's panels go, and how they stay inside the window when it shrinks or grows: a panel still at
// its default place follows the defaults of the new size; one the user moved or resized is anchored to the
// window edges nearest to it (a panel on the right keeps its distance to the right edge) and keeps the size
// the user gave it where the window allows; every panel is clamped inside every frame. Shrinking and
// growing back returns the panels to where they were; "Reset layout" puts them at their defaults. Plain C++
// (tests/cpu/test_panel_layout.cpp); panel_placement.cpp applies it to the ImGui windows.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "ui/label_placement.h"

namespace raylab {

enum class Panel { Method, Timing, SpeedAccuracy, SceneCamera };
constexpr Panel kAllPanels[] = {Panel::Method, Panel::Timing, Panel::SpeedAccuracy, Panel::SceneCamera};
const char* panelTitle(Panel panel);  // the ImGui window name, also the key in imgui.ini

// The default place of a panel in a display of that size: method over scene and camera on the left,
// timing over speed vs accuracy on the right, all inside the display.
Box defaultPanelBox(Panel panel, float displayWidth, float displayHeight);

// Where the heatmap legend is docked: at the bottom of the gap between the default columns, so that it
// covers none of the panels at their defaults; a fixed box, the same for every view.
Box heatmapLegendBox(float displayWidth, float displayHeight);
constexpr const char* kHeatmapLegendTitle = "Heatmap legend";

// `box` moved (and, where it is larger, shrunk) to lie inside the display.
Box clampToDisplay(Box box, float displayWidth, float displayHeight);

struct PanelRect {
  std::string title;
  Box box;
  bool collapsed = false;
  float hiddenHeight = 0.0f;  // content below the panel's bottom edge (ImGui's scroll range): 0 when it all shows
  float clippedWidth = 0.0f;  // content cut off at its right edge (ui/clip_check.h): 0 when nothing is
  std::vector<std::string> clippedItems;  // combo values cut inside their box
};

class PanelLayout {
 public:
  // Every frame for every panel, with where ImGui has it: returns where it must be. A box that differs from
  // the last one returned is the user's doing and becomes the panel's preferred place; a change of display
  // size moves the panel by its anchors from that preferred place. A collapsed panel keeps its size.
  // `hiddenHeight` (its content below the bottom edge) is only recorded.
  Box keepInside(Panel panel, const Box& actual, bool collapsed, float displayWidth, float displayHeight,
                 float hiddenHeight = 0.0f);
  void forget() { entries_.clear(); }  // after a reset: the defaults become the preferred places
  // Where each panel was drawn this frame (before any correction), in call order.
  const std::vector<PanelRect>& rects() const { return rects_; }
  // A window placed by other means (the heatmap legend), listed with the panels.
  void record(const std::string& title, const Box& drawn, bool collapsed = false, float hiddenHeight = 0.0f);
  void startFrame() { rects_.clear(); }
  // What the panel recorded last (by keepInside or record) cut off at its right edge.
  void setClipping(float clippedWidth, std::vector<std::string> items) {
    if (rects_.empty()) return;
    rects_.back().clippedWidth = clippedWidth;
    rects_.back().clippedItems = std::move(items);
  }

 private:
  struct Anchored {
    bool right = false, bottom = false;  // measured from the right / bottom edge
    float offsetX = 0, offsetY = 0;      // from that edge to the panel's near side
    float width = 0, height = 0;
  };
  struct Entry {
    bool atDefault = false;  // never moved by the user: follows defaultPanelBox
    Anchored preferred;
    Box lastReturned;
    float displayWidth = 0, displayHeight = 0;
  };
  static Anchored anchor(const Box& box, float displayWidth, float displayHeight);
  static Box place(const Anchored& a, float displayWidth, float displayHeight);
  std::map<Panel, Entry> entries_;
  std::vector<PanelRect> rects_;
};

// {"display": [w, h], "rects": [{"title", "x", "y", "width", "height", "collapsed", "hidden_height",
// "clipped_width", "clipped_items"}, ...]}: in
// the window screenshot's sidecar, so tests can check that every panel is inside the window and which panels
// must be scrolled to reach their controls.
nlohmann::json panelRectsJson(const std::vector<PanelRect>& rects, float displayWidth, float displayHeight);

}  // namespace raylab
