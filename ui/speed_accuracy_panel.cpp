#include "ui/speed_accuracy_panel.h"

#include <algorithm>

#include <imgui.h>

#include "ui/clip_check.h"
#include "ui/panel_layout.h"
#include "ui/scatter_plot.h"

namespace raylab {
namespace {

using Baseline = MethodKey::Baseline;

const char* const kXAxes[] = {"trace ms", "frame ms (GPU)", "trace + reorder ms"};
const char* const kYAxes[] = {"prediction error", "cell-hit rate", "warp efficiency"};
// The plot's title for each y axis (short: it must fit a narrow panel), and the whole story on hover.
const char* const kYTitles[] = {"prediction error (lower is better)", "cell-hit rate (higher is better)",
                                "virtual warp efficiency, bounces >= 1"};
const char* const kYHelp[] = {
    "the bench's prediction_error_mean: |estimated - actual end point| / scene diagonal, mean over bounces >= 1",
    "the bench's cell_hit_rate: how often the estimated end point's grid cell is the actual one, bounces >= 1",
    "the bench's virtual_warp_efficiency_after_first: sum(n) / (32 max n) per warp of traversal steps n"};

double xOf(const SpeedAccuracyPoint& p, int axis) {
  if (axis == 1) return p.frameMs.value();
  double trace = p.traceMs.value();
  if (axis == 0 || trace < 0.0) return trace;
  return trace + std::max(0.0, p.reorderMs.value());
}

double yOf(const SpeedAccuracyPoint& p, int axis) {
  if (axis == 0) return p.predictionError.value();
  if (axis == 1) return p.cellHitRate.value();
  return p.warpEfficiency.value();
}

void cell(double v, const char* format, double scale = 1.0) {
  ImGui::TableNextColumn();
  if (v < 0.0) ImGui::TextDisabled("n/a");
  else ImGui::Text(format, v * scale);
}

// The plot's legend and figures: number, method (wrapped: the whole name, no sideways scrolling, which hid
// every column after "trace" at 1280x720), frames and the two values plotted; every figure of a row on hovering
// its method.
void drawTable(const SpeedAccuracyBook& book, const SpeedAccuracyView& view, float height) {
  const ImGuiTableFlags flags = ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY |
                                ImGuiTableFlags_SizingStretchProp | ImGuiTableFlags_NoSavedSettings;
  if (!ImGui::BeginTable("points", 5, flags, ImVec2(0, height))) return;
  ImGui::TableSetupScrollFreeze(0, 1);
  // Fixed columns as wide as their header or their widest figure, whichever is wider (a header cut to "frame...").
  const float number = ImGui::CalcTextSize("000.00").x;
  auto fixed = [&](const char* header, float figure) {
    ImGui::TableSetupColumn(header, ImGuiTableColumnFlags_WidthFixed, std::max(ImGui::CalcTextSize(header).x, figure));
  };
  fixed("#", ImGui::CalcTextSize("00").x);
  ImGui::TableSetupColumn("method", ImGuiTableColumnFlags_WidthStretch);
  fixed("frames", 0.0f);
  fixed(view.xAxis == 1 ? "frame ms" : view.xAxis == 2 ? "+reorder" : "trace ms", number);
  fixed(view.yAxis == 0 ? "error" : view.yAxis == 1 ? "cell hit" : "warp eff.", number);
  ImGui::TableHeadersRow();
  const SpeedAccuracyPoint* current = book.current();
  for (const SpeedAccuracyPoint& p : book.points()) {
    ImGui::TableNextRow();
    if (&p == current) ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg0, IM_COL32(90, 75, 20, 255));
    ImGui::TableNextColumn(), ImGui::Text("%d", p.number);
    ImGui::TableNextColumn(), ImGui::TextWrapped("%s", p.label.c_str());
    const bool hovered = ImGui::IsItemHovered();
    ImGui::TableNextColumn(), ImGui::Text("%u", p.frames);
    cell(xOf(p, view.xAxis), "%.2f");
    if (view.yAxis == 0) cell(yOf(p, 0), "%.4f");
    else cell(yOf(p, view.yAxis), "%.1f%%", 100.0);
    if (hovered) {
      auto v = [](double x, double scale = 1.0) { return x < 0.0 ? -1.0 : x * scale; };
      ImGui::SetTooltip("#%d %s\n%u frames; trace %.2f ms, reorder %.2f ms, frame %.2f ms\n"
                        "prediction error %.4f, cell hit %.1f%%, warp efficiency %.1f%% (-1: not measured)",
                        p.number, p.label.c_str(), p.frames, v(p.traceMs.value()), v(p.reorderMs.value()),
                        v(p.frameMs.value()), v(p.predictionError.value()), v(p.cellHitRate.value(), 100.0),
                        v(p.warpEfficiency.value(), 100.0));
    }
  }
  ImGui::EndTable();
}

void drawPlot(const SpeedAccuracyBook& book, const SpeedAccuracyView& view, float height) {
  std::vector<ScatterPoint> points;
  std::vector<ReferenceLine> lines;
  std::string hidden;
  const SpeedAccuracyPoint* current = book.current();
  for (const SpeedAccuracyPoint& p : book.points()) {
    double x = xOf(p, view.xAxis);
    if (x < 0.0) {  // a megakernel has no trace stage
      hidden += (hidden.empty() ? "" : ", ") + p.label;
      continue;
    }
    double y = yOf(p, view.yAxis);
    if (p.key.baseline != Baseline::None) {
      // Numbered as the table's rows: "unsorted" split and fused drew two lines with one tag.
      lines.push_back({x, std::to_string(p.number) + " " + p.label});
      if (y < 0.0) continue;  // the line is the baseline: no point in the "no value" strip
    }
    points.push_back({x, y, std::to_string(p.number), std::to_string(p.number) + " " + p.label, &p == current});
  }
  const ScatterAxes axes{kXAxes[view.xAxis], kYTitles[view.yAxis],
                         view.yAxis == 2 ? "n/a: not measured (detailed stats off, or the rt tracer)"
                                         : "n/a: no prediction (a baseline, or a key with no end point)"};
  const bool anyY = std::any_of(points.begin(), points.end(), [](const ScatterPoint& p) { return p.y >= 0.0; });
  drawScatter("speed-accuracy", points, lines, axes, height,
              points.empty() && lines.empty() ? "no frame measured yet"
              : anyY                           ? ""
              : view.yAxis == 2                ? "no method here has a warp efficiency: turn on detailed stats"
                                               : "no method here predicts an end point (baselines and strategy none do "
                                                 "not): pick a key strategy, or y: warp efficiency");
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
  ImGui::TextWrapped("dots: methods, dashed: baselines; numbers: the table's rows");
  ImGui::PopStyleColor();
  if (!hidden.empty()) ImGui::TextWrapped("not on this axis (no trace stage): %s", hidden.c_str());
}

// Why the current method has no point on the accuracy axes.
void explainCurrent(const SpeedAccuracyBook& book, const Settings& settings) {
  const SpeedAccuracyPoint* p = book.current();
  if (!p) {
    ImGui::TextDisabled("no frame measured yet");
    return;
  }
  ImGui::TextWrapped("now: #%d %s (%u frames)", p->number, p->label.c_str(), p->frames);
  if (p->predictionError.value() >= 0.0) return;
  const char* why = p->key.baseline != Baseline::None ? "a baseline predicts nothing"
                    : settings.strategy == KeyStrategy::DeadLast || settings.strategy == KeyStrategy::Origin ||
                            settings.strategy == KeyStrategy::Direction || settings.strategy == KeyStrategy::OriginDirection
                        ? "this key predicts no end point"
                        : "prediction is measured with detailed stats on";
  ImGui::TextDisabled("no prediction error: %s", why);
}

}  // namespace

void drawSpeedAccuracyPanel(SpeedAccuracyBook& book, BaselineRun& baselines, SpeedAccuracyView& view, Settings& settings) {
  if (!ImGui::Begin(panelTitle(Panel::SpeedAccuracy))) {
    ImGui::End();
    return;
  }
  if (baselines.active()) {
    ImGui::TextUnformatted(baselines.status().c_str());
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) baselines.cancel(settings);
  } else if (ImGui::Button("Measure baselines")) {
    baselines.start(settings);
  }
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("render a few frames unsorted and with the megakernel, then go back");
  ImGui::SameLine();
  if (ImGui::Button("Clear")) book.clear();
  explainCurrent(book, settings);
  // Each axis on a row of its own: side by side at 1280x720 the y combo cut "virtual warp effici".
  const float width = ImGui::GetContentRegionAvail().x - ImGui::CalcTextSize("x").x - ImGui::GetStyle().ItemInnerSpacing.x;
  ImGui::SetNextItemWidth(width);
  fitsCombo(kXAxes[view.xAxis]);
  ImGui::Combo("x", &view.xAxis, kXAxes, IM_ARRAYSIZE(kXAxes));
  ImGui::SetNextItemWidth(width);
  fitsCombo(kYAxes[view.yAxis]);
  ImGui::Combo("y", &view.yAxis, kYAxes, IM_ARRAYSIZE(kYAxes));
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", kYHelp[view.yAxis]);
  const float avail = ImGui::GetContentRegionAvail().y;
  const float plotHeight = std::max(120.0f, 0.6f * avail - ImGui::GetTextLineHeightWithSpacing());
  drawPlot(book, view, plotHeight);
  drawTable(book, view, std::max(3.0f * ImGui::GetFrameHeight(), ImGui::GetContentRegionAvail().y));
  ImGui::End();
}

}  // namespace raylab
