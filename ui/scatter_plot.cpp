#include "ui/scatter_plot.h"

#include <algorithm>
#include <cstdio>

#include <imgui.h>

namespace raylab {

void drawScatter(const char* id, const std::vector<ScatterPoint>& points, const char* xLabel, const char* yLabel,
                 double yMax, float height) {
  ImGui::PushID(id);
  const float width = ImGui::GetContentRegionAvail().x;
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::Dummy(ImVec2(width, height));
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const float margin = 30.0f, line = ImGui::GetTextLineHeight();
  const ImVec2 lo(origin.x + margin, origin.y + height - line - 4), hi(origin.x + width - 8, origin.y + 4);
  draw->AddRectFilled(ImVec2(lo.x, hi.y), ImVec2(hi.x, lo.y), IM_COL32(25, 25, 30, 255));
  draw->AddLine(lo, ImVec2(hi.x, lo.y), IM_COL32(160, 160, 160, 255));
  draw->AddLine(lo, ImVec2(lo.x, hi.y), IM_COL32(160, 160, 160, 255));

  double xMax = 0.0, yTop = yMax;
  for (const ScatterPoint& p : points) {
    xMax = std::max(xMax, p.x);
    if (yMax <= 0.0) yTop = std::max(yTop, p.y);
  }
  xMax = xMax > 0.0 ? xMax * 1.1 : 1.0;
  yTop = yTop > 0.0 ? yTop * (yMax <= 0.0 ? 1.1 : 1.0) : 1.0;
  char text[64];
  std::snprintf(text, sizeof(text), "%s (0..%.3g)", xLabel, xMax);
  draw->AddText(ImVec2(lo.x, lo.y + 2), IM_COL32(200, 200, 200, 255), text);
  std::snprintf(text, sizeof(text), "%s (0..%.3g)", yLabel, yTop);
  draw->AddText(ImVec2(lo.x + 4, hi.y), IM_COL32(200, 200, 200, 255), text);

  for (const ScatterPoint& p : points) {
    ImVec2 at(lo.x + static_cast<float>(p.x / xMax) * (hi.x - lo.x), lo.y - static_cast<float>(p.y / yTop) * (lo.y - hi.y));
    ImU32 color = p.highlight ? IM_COL32(255, 210, 60, 255) : IM_COL32(120, 190, 255, 255);
    draw->AddCircleFilled(at, p.highlight ? 5.0f : 3.5f, color);
    // Labels go left of points near the right edge, so they stay inside the plot.
    float labelWidth = ImGui::CalcTextSize(p.label.c_str()).x;
    float x = at.x + 5 + labelWidth > hi.x ? at.x - 5 - labelWidth : at.x + 5;
    draw->AddText(ImVec2(x, at.y - line), color, p.label.c_str());
  }
  ImGui::PopID();
}

}  // namespace raylab
