#include "ui/heatmap_legend.h"

#include <algorithm>
#include <cstdio>

#include <imgui.h>

#include "renderer/heatmap/heatmap_colours.h"
#include "renderer/heatmap/heatmap_rules.h"
#include "ui/panel_layout.h"

namespace raylab {
namespace {

ImU32 toColor(const glm::vec3& c) {
  uint32_t p = packColour(c);  // the bytes the image holds: R low, as ImU32 is
  return ImU32(p);
}

void swatch(const glm::vec3& colour, const char* text) {
  ImVec2 p = ImGui::GetCursorScreenPos();
  float h = ImGui::GetTextLineHeight();
  ImGui::GetWindowDrawList()->AddRectFilled(p, ImVec2(p.x + h, p.y + h), toColor(colour));
  ImGui::GetWindowDrawList()->AddRect(p, ImVec2(p.x + h, p.y + h), IM_COL32(150, 150, 150, 255));
  ImGui::Dummy(ImVec2(h, h));
  ImGui::SameLine();
  ImGui::TextUnformatted(text);
}

// Text that wraps at the legend's edge rather than running out of it, at full contrast: dim grey over a
// noisy heatmap could not be read.
void wrapped(const char* text) { ImGui::TextWrapped("%s", text); }

void drawRamp(const HeatmapStats& h) {
  const float width = std::min(260.0f, ImGui::GetContentRegionAvail().x), height = 14.0f;
  ImVec2 p = ImGui::GetCursorScreenPos();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const int steps = 32;
  for (int i = 0; i < steps; ++i) {
    float x0 = p.x + width * i / steps, x1 = p.x + width * (i + 1) / steps;
    ImU32 a = toColor(heatmapRamp(float(i) / steps)), b = toColor(heatmapRamp(float(i + 1) / steps));
    draw->AddRectFilledMultiColor(ImVec2(x0, p.y), ImVec2(x1, p.y + height), a, b, b, a);
  }
  ImGui::Dummy(ImVec2(width, height));
  ImGui::Text("%.4g", h.min);
  char hi[32];
  std::snprintf(hi, sizeof(hi), "%.4g", h.max);
  ImGui::SameLine(width - ImGui::CalcTextSize(hi).x + ImGui::GetStyle().WindowPadding.x);
  ImGui::TextUnformatted(hi);
  ImGui::Text("%s, %s scale", h.unit.c_str(), h.scale.c_str());
}

// Lock keeps the colours comparable across frames and strategies: checking it takes this frame's range.
void drawRangeControls(HeatmapRange& range, const HeatmapStats& h) {
  bool locked = range.locked;
  if (ImGui::Checkbox("lock range", &locked)) {
    range.locked = locked;
    if (locked && h.frameMax > h.frameMin)
      range.min = float(h.frameMin), range.max = float(h.frameMax);
  }
  ImGui::SameLine();
  ImGui::TextDisabled("frame: %.4g .. %.4g", h.frameMin, h.frameMax);
  if (!range.locked) return;
  float ends[2] = {range.min, range.max};
  ImGui::SetNextItemWidth(200);
  if (ImGui::InputFloat2("min / max", ends, "%.4g")) {
    const float top = SettingLimits::kMaxHeatmapValue;
    ends[0] = std::clamp(ends[0], 0.0f, top);
    ends[1] = std::clamp(ends[1], 0.0f, top);
    if (ends[0] < ends[1]) range.min = ends[0], range.max = ends[1];  // an empty interval is not taken
  }
}

void drawProbe(const HeatmapProbe& q, const HeatmapStats& h) {
  if (!q.valid) {
    wrapped("hover the image for a pixel's value, key, cell and path");
    return;
  }
  // The number itself on the pixel's line ("value" stood where a number belongs); the reason where none.
  if (q.state != "value") ImGui::Text("pixel (%u, %u): %s", q.x, q.y, q.state.c_str());
  else if (h.keyColour == "cell" || h.keyColour == "hash")
    ImGui::Text("pixel (%u, %u): key %u (0x%08x)", q.x, q.y, uint32_t(q.value), uint32_t(q.value));
  else ImGui::Text("pixel (%u, %u): %.6g %s", q.x, q.y, q.value, h.unit.c_str());
  if (q.hasPath) ImGui::Text("  path id %u", q.pathId);
  if (q.hasKey && h.keyColour == "rank") ImGui::Text("  key %u (0x%08x)", q.key, q.key);
  if (q.hasCell) ImGui::Text("  %s (%u, %u, %u), direction octant %u", q.cellKind.c_str(), q.cell.x, q.cell.y, q.cell.z, q.octant);
}

void drawCounts(const HeatmapStats& h) {
  if (h.pixels == 0) return;
  auto pct = [&](uint32_t n) { return 100.0 * n / h.pixels; };
  swatch(noPathColour(), "no path at this bounce");
  ImGui::SameLine();
  ImGui::TextDisabled("%.1f%%", pct(h.pixelsWithoutPath));
  if (!h.noValueMeaning.empty()) {
    swatch(noValueColour(), h.noValueMeaning.c_str());
    ImGui::SameLine();
    ImGui::TextDisabled("%.1f%%", pct(h.pixelsWithoutValue));
  }
}

}  // namespace

const char* heatmapDescription(HeatmapView view, HeatmapKeyColour keyColour) {
  switch (view) {
    case HeatmapView::None: return "the render";
    case HeatmapView::SortKey:
      switch (keyColour) {
        case HeatmapKeyColour::Cell: return "sort key per pixel, coloured by the cell it encodes (x red, y green, z blue over the cells in view)";
        case HeatmapKeyColour::Rank: return "sort key per pixel, by its rank among the bounce's sorted keys";
        case HeatmapKeyColour::Hash: return "sort key per pixel, hashed: equal keys share a colour";
      }
      return "";
    case HeatmapView::CellHit: return "estimated end-point cell against the actual cell";
    case HeatmapView::TraversalSteps: return "BVH traversal steps per pixel";
    case HeatmapView::WarpEfficiency: return "efficiency of the 32-wide warp each path was traced in";
    case HeatmapView::CacheMean: return "length-cache mean at the path's cell and octant";
    case HeatmapView::CacheVariance: return "length-cache variance at the path's cell and octant";
  }
  return "";
}

bool drawHeatmapLegend(Settings& settings, const FrameStats& stats, const Box& box) {
  if (settings.heatmap == HeatmapView::None) return false;
  ImGui::SetNextWindowPos(ImVec2(box.x0, box.y0), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(box.x1 - box.x0, box.y1 - box.y0), ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(0.92f);  // text over a noisy heatmap must stay readable
  // No title bar, move or resize: a fixed place (panel_layout.h) that never covers the panels.
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove |
                                 ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
                                 ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav;
  if (ImGui::Begin(kHeatmapLegendTitle, nullptr, flags)) {
    ImGui::PushTextWrapPos(0.0f);
    if (std::optional<std::string> why = heatmapUnavailable(settings)) {
      // The renderer draws the render instead (heatmapShown); say why rather than show an empty view.
      ImGui::Text("%s is not available", toString(settings.heatmap).c_str());
      ImGui::TextWrapped("%s", why->c_str());
      ImGui::PopTextWrapPos();
      ImGui::End();
      return true;
    }
    const HeatmapStats& h = stats.heatmap;
    ImGui::Text("%s, bounce %u", toString(settings.heatmap).c_str(), heatmapBounceShown(settings));
    wrapped(heatmapDescription(settings.heatmap, settings.heatmapKeyColour));
    if (!h.emptyReason.empty()) ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "nothing to show: %s", h.emptyReason.c_str());
    if (settings.heatmap == HeatmapView::CellHit) {
      swatch(cellHitColour(true), "hit: estimated cell is the actual cell");
      swatch(cellHitColour(false), "miss");
    } else if (settings.heatmap == HeatmapView::SortKey && h.keyColour != "rank") {
      ImGui::Text("keys %.10g .. %.10g", h.frameMin, h.frameMax);
    } else {
      drawRamp(h);
      if (settings.heatmap != HeatmapView::SortKey) drawRangeControls(settings.heatmapRange, h);
    }
    drawCounts(h);
    ImGui::Separator();
    drawProbe(h.probe, h);
    ImGui::PopTextWrapPos();
  }
  ImGui::End();
  return true;
}

}  // namespace raylab
