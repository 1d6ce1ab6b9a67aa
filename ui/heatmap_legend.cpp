#include "ui/heatmap_legend.h"

#include <algorithm>
#include <cstdio>

#include <imgui.h>

#include "renderer/heatmap_rules.h"

namespace raylab {
namespace {

ImU32 toColor(const glm::vec3& c) {
  glm::vec3 v = glm::clamp(c, 0.0f, 1.0f) * 255.0f;
  return IM_COL32(int(v.r), int(v.g), int(v.b), 255);
}

void swatch(ImU32 color, const char* text) {
  ImVec2 p = ImGui::GetCursorScreenPos();
  float h = ImGui::GetTextLineHeight();
  ImGui::GetWindowDrawList()->AddRectFilled(p, ImVec2(p.x + h, p.y + h), color);
  ImGui::GetWindowDrawList()->AddRect(p, ImVec2(p.x + h, p.y + h), IM_COL32(150, 150, 150, 255));
  ImGui::Dummy(ImVec2(h, h));
  ImGui::SameLine();
  ImGui::TextUnformatted(text);
}

void drawRamp(const FrameStats& stats) {
  const float width = 260.0f, height = 14.0f;
  ImVec2 p = ImGui::GetCursorScreenPos();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const int steps = 32;
  for (int i = 0; i < steps; ++i) {
    float x0 = p.x + width * i / steps, x1 = p.x + width * (i + 1) / steps;
    draw->AddRectFilledMultiColor(ImVec2(x0, p.y), ImVec2(x1, p.y + height), toColor(heatmapRamp(float(i) / steps)),
                                  toColor(heatmapRamp(float(i + 1) / steps)), toColor(heatmapRamp(float(i + 1) / steps)),
                                  toColor(heatmapRamp(float(i) / steps)));
  }
  ImGui::Dummy(ImVec2(width, height));
  ImGui::Text("%.4g", stats.heatmapMin);
  char hi[32];
  std::snprintf(hi, sizeof(hi), "%.4g", stats.heatmapMax);
  ImGui::SameLine(width - ImGui::CalcTextSize(hi).x + ImGui::GetStyle().WindowPadding.x);
  ImGui::TextUnformatted(hi);
  if (!stats.heatmapUnit.empty()) ImGui::Text("unit: %s", stats.heatmapUnit.c_str());
  if (stats.heatmapMax <= stats.heatmapMin) ImGui::TextDisabled("(no range reported yet)");
}

}  // namespace

glm::vec3 heatmapRamp(float t) {
  const float x = std::clamp(t, 0.0f, 1.0f);
  const glm::vec4 v4(1.0f, x, x * x, x * x * x);
  const glm::vec2 v2 = glm::vec2(v4.z, v4.w) * v4.z;
  const glm::vec4 r4(0.13572138f, 4.61539260f, -42.66032258f, 132.13108234f);
  const glm::vec4 g4(0.09140261f, 2.19418839f, 4.84296658f, -14.18503333f);
  const glm::vec4 b4(0.10667330f, 12.64194608f, -60.58204836f, 110.36276771f);
  const glm::vec2 r2(-152.94239396f, 59.28637943f), g2(4.27729857f, 2.82956604f), b2(-89.90310912f, 27.34824973f);
  return glm::clamp(glm::vec3(glm::dot(v4, r4) + glm::dot(v2, r2), glm::dot(v4, g4) + glm::dot(v2, g2),
                              glm::dot(v4, b4) + glm::dot(v2, b2)),
                    0.0f, 1.0f);
}

const char* heatmapDescription(HeatmapView view) {
  switch (view) {
    case HeatmapView::None: return "the render";
    case HeatmapView::SortKey: return "sort key per pixel, hashed: equal keys share a colour";
    case HeatmapView::CellHit: return "estimated end-point cell against the actual cell";
    case HeatmapView::TraversalSteps: return "BVH traversal steps per pixel";
    case HeatmapView::WarpEfficiency: return "efficiency of the 32-wide warp each path was traced in";
    case HeatmapView::CacheMean: return "length-cache mean at the path's cell and octant";
    case HeatmapView::CacheVariance: return "length-cache variance at the path's cell and octant";
  }
  return "";
}

void drawHeatmapLegend(const Settings& settings, const FrameStats& stats) {
  if (settings.heatmap == HeatmapView::None) return;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y - 10), ImGuiCond_Always, ImVec2(0.5f, 1.0f));
  ImGui::SetNextWindowBgAlpha(0.75f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                 ImGuiWindowFlags_NoNav;
  if (ImGui::Begin("Heatmap legend", nullptr, flags)) {
    if (std::optional<std::string> why = heatmapUnavailable(settings)) {
      // The renderer draws the render instead (heatmapShown); say why rather than show an empty view.
      ImGui::Text("%s is not available", toString(settings.heatmap).c_str());
      ImGui::TextUnformatted(why->c_str());
      ImGui::End();
      return;
    }
    ImGui::Text("%s, bounce %u", toString(settings.heatmap).c_str(), heatmapBounceShown(settings));
    ImGui::TextDisabled("%s", heatmapDescription(settings.heatmap));
    if (settings.heatmap == HeatmapView::CellHit) {
      swatch(IM_COL32(51, 204, 77, 255), "hit: estimated cell is the actual cell");
      swatch(IM_COL32(217, 51, 51, 255), "miss");
    } else if (settings.heatmap == HeatmapView::SortKey) {
      ImGui::Text("keys %.6g .. %.6g", stats.heatmapMin, stats.heatmapMax);
    } else {
      drawRamp(stats);
    }
    swatch(IM_COL32(31, 31, 31, 255), "no path at this bounce");
  }
  ImGui::End();
}

}  // namespace raylab
