#include "ui/scatter_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <imgui.h>

#include "ui/label_placement.h"

namespace raylab {
namespace {

constexpr float kMarker = 4.0f;
const ImU32 kAxis = IM_COL32(160, 160, 160, 255), kText = IM_COL32(200, 200, 200, 255);
const ImU32 kPointColor = IM_COL32(120, 190, 255, 255), kHighlight = IM_COL32(255, 210, 60, 255);
const ImU32 kLineColor = IM_COL32(230, 120, 120, 255);

std::string format(double v) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.3g", v);
  return text;
}

struct Range {
  double lo = 0.0, hi = 1.0;
};

// The values' span with a tenth of it to spare on each side (a tenth of the value when they are all equal),
// not below zero: every value here is a time or a rate.
Range rangeOf(const std::vector<double>& values) {
  if (values.empty()) return {};
  auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  double pad = 0.1 * (*hi - *lo);
  if (pad <= 0.0) pad = std::max(0.1 * std::abs(*hi), 1e-6);
  return {std::max(0.0, *lo - pad), *hi + pad};
}

void dashedVertical(ImDrawList* draw, float x, float y0, float y1, ImU32 color) {
  for (float y = y0; y < y1; y += 6.0f) draw->AddLine(ImVec2(x, y), ImVec2(x, std::min(y + 3.0f, y1)), color);
}

}  // namespace

void drawScatter(const char* id, const std::vector<ScatterPoint>& points, const std::vector<ReferenceLine>& lines,
                 const ScatterAxes& axes, float height, const std::string& empty) {
  ImGui::PushID(id);
  const float width = std::max(80.0f, ImGui::GetContentRegionAvail().x);
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::Dummy(ImVec2(width, height));
  const bool hovered = ImGui::IsItemHovered();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->PushClipRect(origin, ImVec2(origin.x + width, origin.y + height), true);
  const float line = ImGui::GetTextLineHeight();

  std::vector<double> xs, ys;
  for (const ScatterPoint& p : points) {
    xs.push_back(p.x);
    if (p.y >= 0.0) ys.push_back(p.y);
  }
  for (const ReferenceLine& l : lines) xs.push_back(l.x);
  const bool anyWithoutY = ys.size() < points.size();
  const Range xr = rangeOf(xs), yr = rangeOf(ys);

  // Rows from the top: y title, plot, strip (points without y), x tick values, x title.
  const std::string yHiText = format(yr.hi), yLoText = format(yr.lo), xHiText = format(xr.hi), xLoText = format(xr.lo);
  const float left = origin.x + std::max({ImGui::CalcTextSize(yHiText.c_str()).x, ImGui::CalcTextSize(yLoText.c_str()).x,
                                          ImGui::CalcTextSize("n/a").x}) + 6.0f;
  const float right = origin.x + width - 4.0f;
  const float top = origin.y + line + 4.0f;
  const float strip = anyWithoutY ? line + 6.0f : 0.0f;
  const float bottom = std::max(top + 20.0f, origin.y + height - 2.0f * line - 6.0f - strip);
  draw->AddText(ImVec2(origin.x, origin.y), kText, axes.y.c_str());
  draw->AddRectFilled(ImVec2(left, top), ImVec2(right, bottom), IM_COL32(25, 25, 30, 255));
  draw->AddLine(ImVec2(left, bottom), ImVec2(right, bottom), kAxis);
  draw->AddLine(ImVec2(left, top), ImVec2(left, bottom), kAxis);
  draw->AddText(ImVec2(origin.x, top), kText, yHiText.c_str());
  draw->AddText(ImVec2(origin.x, bottom - line), kText, yLoText.c_str());
  if (anyWithoutY) {
    draw->AddRectFilled(ImVec2(left, bottom + 2.0f), ImVec2(right, bottom + strip), IM_COL32(35, 30, 30, 255));
    draw->AddText(ImVec2(origin.x, bottom + 3.0f), IM_COL32(150, 150, 150, 255), "n/a");
  }
  const float ticks = bottom + strip + 2.0f;
  draw->AddText(ImVec2(left, ticks), kText, xLoText.c_str());
  draw->AddText(ImVec2(right - ImGui::CalcTextSize(xHiText.c_str()).x, ticks), kText, xHiText.c_str());
  const float titleWidth = ImGui::CalcTextSize(axes.x.c_str()).x;
  draw->AddText(ImVec2(std::max(left, 0.5f * (left + right - titleWidth)), ticks + line + 2.0f), kText, axes.x.c_str());

  auto screenX = [&](double x) { return left + static_cast<float>((x - xr.lo) / (xr.hi - xr.lo)) * (right - left); };
  auto screenY = [&](double y) {
    return y < 0.0 ? bottom + 0.5f * (strip + 2.0f) : bottom - static_cast<float>((y - yr.lo) / (yr.hi - yr.lo)) * (bottom - top);
  };
  // Tags of reference lines at their tops, then the points' tags, placed together so none overlaps.
  std::vector<LabelRequest> requests;
  std::vector<ImVec2> anchors;
  for (const ReferenceLine& l : lines) {
    float x = screenX(l.x);
    dashedVertical(draw, x, top, bottom + strip, kLineColor);
    ImVec2 size = ImGui::CalcTextSize(l.tag.c_str());
    anchors.push_back(ImVec2(x, top + 2.0f));
    requests.push_back({x, top + 2.0f, size.x, size.y});
  }
  const ScatterPoint* under = nullptr;
  for (const ScatterPoint& p : points) {
    ImVec2 at(screenX(p.x), screenY(p.y));
    ImVec2 size = ImGui::CalcTextSize(p.tag.c_str());
    anchors.push_back(at);
    requests.push_back({at.x, at.y, size.x, size.y});
    if (hovered) {
      ImVec2 m = ImGui::GetIO().MousePos;
      if ((m.x - at.x) * (m.x - at.x) + (m.y - at.y) * (m.y - at.y) < 36.0f) under = &p;
    }
  }
  std::vector<LabelPlacement> placed = placeLabels(requests, {left + 1.0f, top + 1.0f, right - 1.0f, bottom + strip}, kMarker);
  for (size_t i = 0; i < placed.size(); ++i) {
    const bool isLine = i < lines.size();
    const ScatterPoint* p = isLine ? nullptr : &points[i - lines.size()];
    ImU32 color = isLine ? kLineColor : p->highlight ? kHighlight : kPointColor;
    const Box& b = placed[i].box;
    if (placed[i].leader) {
      ImVec2 to(std::clamp(anchors[i].x, b.x0, b.x1), std::clamp(anchors[i].y, b.y0, b.y1));
      draw->AddLine(anchors[i], to, (color & 0x00FFFFFFu) | 0x90000000u);
    }
    if (!isLine) {
      if (p->y < 0.0) draw->AddCircle(anchors[i], kMarker, color, 0, 1.5f);
      else draw->AddCircleFilled(anchors[i], p->highlight ? kMarker + 1.5f : kMarker, color);
    }
    draw->AddText(ImVec2(b.x0, b.y0), color, isLine ? lines[i].tag.c_str() : p->tag.c_str());
  }
  if (!empty.empty()) {  // wrapped inside the plot area, so the reader sees why it is empty
    const float wrap = right - left - 12.0f;
    const ImVec2 size = ImGui::CalcTextSize(empty.c_str(), nullptr, false, wrap);
    draw->AddText(ImGui::GetFont(), ImGui::GetFontSize(), ImVec2(left + 6.0f, std::max(top + 4.0f, 0.5f * (top + bottom - size.y))),
                  IM_COL32(235, 200, 120, 255), empty.c_str(), nullptr, wrap);
  }
  draw->PopClipRect();
  if (under) ImGui::SetTooltip("%s", under->tooltip.c_str());
  else if (hovered && anyWithoutY && ImGui::GetIO().MousePos.y > bottom && ImGui::GetIO().MousePos.y < bottom + strip)
    ImGui::SetTooltip("%s", axes.noValue.c_str());
  ImGui::PopID();
}

}  // namespace raylab
