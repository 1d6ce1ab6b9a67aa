#include "ui/panel_layout.h"

#include <algorithm>
#include <cmath>

namespace raylab {
namespace {

constexpr float kMargin = 10.0f;
constexpr float kLegendMinWidth = 280.0f, kLegendMaxWidth = 420.0f;
// The legend covers at most this share of the display (issue 38: at 1280x720 a 480x300 box hid most of the
// image between the panels). A tenth, not less: at 0.095 the cache-mean legend's last line lost 2 px at
// 1280x720 (208 px high; its text needs 210).
constexpr float kLegendMaxShare = 0.0999f;  // a hair under: float rounding must not cross the tenth

// The default widths of the left and right columns: a share of the display, so a larger window gives the
// panels room too (at 1600x900 they kept their 1280x720 widths and cut their text the same way). The gap
// between them shows the image and, at its bottom, the heatmap legend: where the columns would leave less
// than the legend needs, both give way in proportion (down to 120 px each).
struct Columns {
  float left, right;
};
Columns columnsFor(float w) {
  float left = std::min(0.27f * w, std::max(120.0f, 0.42f * w - 1.5f * kMargin));
  float right = std::min(0.31f * w, std::max(120.0f, w - left - 3.0f * kMargin));
  const float short_ = kLegendMinWidth - (w - left - right - 4.0f * kMargin);
  if (short_ > 0.0f) {
    const float keep = std::max(0.0f, 1.0f - short_ / (left + right));
    left = std::max(120.0f, left * keep), right = std::max(120.0f, right * keep);
  }
  return {left, right};
}

bool near(const Box& a, const Box& b) {
  return std::abs(a.x0 - b.x0) <= 1 && std::abs(a.y0 - b.y0) <= 1 && std::abs(a.x1 - b.x1) <= 1 && std::abs(a.y1 - b.y1) <= 1;
}

}  // namespace

const char* panelTitle(Panel panel) {
  switch (panel) {
    case Panel::Method: return "Method";
    case Panel::Timing: return "Timing";
    case Panel::SpeedAccuracy: return "Speed vs accuracy";
    case Panel::SceneCamera: return "Scene and camera";
  }
  return "";
}

Box defaultPanelBox(Panel panel, float w, float h) {
  // Two columns as wide as their contents want, narrower in a small window; each split top and bottom.
  const auto [left, right] = columnsFor(w);
  const float usable = std::max(60.0f, h - 3.0f * kMargin);
  // Speed vs accuracy gets the larger share on the right: its plot and table need it; timing scrolls. The
  // Method panel's keys tab needs 418 px: at 1280x720 (usable 696) 0.62 of the height shows it whole.
  const float methodHeight = std::min(540.0f, 0.62f * usable), timingHeight = 0.45f * usable;
  Box b;
  switch (panel) {
    case Panel::Method: b = {kMargin, kMargin, kMargin + left, kMargin + methodHeight}; break;
    case Panel::SceneCamera: b = {kMargin, 2 * kMargin + methodHeight, kMargin + left, h - kMargin}; break;
    case Panel::Timing: b = {w - kMargin - right, kMargin, w - kMargin, kMargin + timingHeight}; break;
    case Panel::SpeedAccuracy: b = {w - kMargin - right, 2 * kMargin + timingHeight, w - kMargin, h - kMargin}; break;
  }
  return clampToDisplay(b, w, h);
}

Box heatmapLegendBox(float w, float h) {
  // At the bottom of the gap between the columns, as wide as the gap allows, and the same whatever the view
  // shows: a legend that sized itself to its text moved with every view and covered the panels.
  const auto [left, right] = columnsFor(w);
  const float gapX0 = 2.0f * kMargin + left, gapX1 = w - 2.0f * kMargin - right;
  const float width = std::min(kLegendMaxWidth, gapX1 - gapX0);
  const float height = std::min({210.0f, 0.45f * std::max(60.0f, h - 3.0f * kMargin), kLegendMaxShare * w * h / width});
  const float x0 = std::floor(0.5f * (gapX0 + gapX1 - width));
  return clampToDisplay({x0, h - kMargin - height, x0 + width, h - kMargin}, w, h);
}

Box clampToDisplay(Box b, float w, float h) {
  const float width = std::min(b.x1 - b.x0, w), height = std::min(b.y1 - b.y0, h);
  const float x = std::floor(std::clamp(b.x0, 0.0f, std::max(0.0f, w - width)));
  const float y = std::floor(std::clamp(b.y0, 0.0f, std::max(0.0f, h - height)));
  return {x, y, x + width, y + height};
}

PanelLayout::Anchored PanelLayout::anchor(const Box& b, float w, float h) {
  Anchored a;
  a.right = 0.5f * (b.x0 + b.x1) > 0.5f * w;
  a.bottom = 0.5f * (b.y0 + b.y1) > 0.5f * h;
  a.offsetX = a.right ? w - b.x1 : b.x0;
  a.offsetY = a.bottom ? h - b.y1 : b.y0;
  a.width = b.x1 - b.x0;
  a.height = b.y1 - b.y0;
  return a;
}

Box PanelLayout::place(const Anchored& a, float w, float h) {
  const float x0 = a.right ? w - a.offsetX - a.width : a.offsetX;
  const float y0 = a.bottom ? h - a.offsetY - a.height : a.offsetY;
  return {x0, y0, x0 + a.width, y0 + a.height};
}

Box PanelLayout::keepInside(Panel panel, const Box& actual, bool collapsed, float w, float h, float hiddenHeight) {
  auto [it, fresh] = entries_.try_emplace(panel);
  Entry& e = it->second;
  Box want = actual;
  if (fresh) {
    e.preferred = anchor(actual, w, h);
    e.atDefault = !collapsed && near(actual, defaultPanelBox(panel, w, h));
  } else if (w != e.displayWidth || h != e.displayHeight) {
    if (e.atDefault) {
      want = defaultPanelBox(panel, w, h);
    } else {
      Anchored a = e.preferred;
      if (collapsed) a.height = actual.y1 - actual.y0;  // its title bar: the full size comes back on expanding
      want = place(a, w, h);
    }
  } else if (!near(actual, e.lastReturned)) {
    // Moved or resized by the user (or expanded/collapsed): that is where it belongs now.
    Anchored a = anchor(actual, w, h);
    if (collapsed) a.height = e.preferred.height;
    e.preferred = a;
    e.atDefault = false;
  }
  Box placed = clampToDisplay(want, w, h);
  e.lastReturned = placed;
  e.displayWidth = w, e.displayHeight = h;
  record(panelTitle(panel), actual, collapsed, hiddenHeight);  // as drawn this frame: what a screenshot shows
  return placed;
}

void PanelLayout::record(const std::string& title, const Box& drawn, bool collapsed, float hiddenHeight) {
  rects_.push_back({title, drawn, collapsed, hiddenHeight});
}

nlohmann::json panelRectsJson(const std::vector<PanelRect>& rects, float w, float h) {
  nlohmann::json list = nlohmann::json::array();
  for (const PanelRect& r : rects)
    list.push_back({{"title", r.title}, {"x", r.box.x0}, {"y", r.box.y0}, {"width", r.box.x1 - r.box.x0},
                    {"height", r.box.y1 - r.box.y0}, {"collapsed", r.collapsed},
                    {"hidden_height", r.hiddenHeight}, {"clipped_width", r.clippedWidth},
                    {"clipped_items", r.clippedItems}});
  return {{"display", {w, h}}, {"rects", list}};
}

}  // namespace raylab
