#include "ui/speed_accuracy_panel.h"

#include <algorithm>

#include <imgui.h>

#include "ui/panel_layout.h"
#include "ui/scatter_plot.h"

namespace raylab {
namespace {

using Baseline = MethodKey::Baseline;

const char* const kXAxes[] = {"trace ms", "frame ms (GPU)", "trace + reorder ms"};
const char* const kYAxes[] = {"prediction error", "cell-hit rate", "virtual warp efficiency"};
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

void drawTable(const SpeedAccuracyBook& book, float height) {
  // The table is the plot's legend, so its method names are shown whole: not resizable, every column fits its
  // widest cell every frame (a resizable fixed column kept the width of its first frame, the header's
  // "method", and cut names to "unsorte"); the table scrolls sideways instead.
  const ImGuiTableFlags flags = ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollX |
                                ImGuiTableFlags_ScrollY | ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_NoSavedSettings;
  if (!ImGui::BeginTable("points", 9, flags, ImVec2(0, height))) return;
  ImGui::TableSetupScrollFreeze(2, 1);  // number and method stay in view while scrolling
  for (const char* h : {"#", "method", "frames", "trace ms", "reorder ms", "frame ms", "pred. error", "cell hit", "warp eff."})
    ImGui::TableSetupColumn(h);
  ImGui::TableHeadersRow();
  const SpeedAccuracyPoint* current = book.current();
  for (const SpeedAccuracyPoint& p : book.points()) {
    ImGui::TableNextRow();
    if (&p == current) ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg0, IM_COL32(90, 75, 20, 255));
    ImGui::TableNextColumn(), ImGui::Text("%d", p.number);
    ImGui::TableNextColumn(), ImGui::TextUnformatted(p.label.c_str());
    ImGui::TableNextColumn(), ImGui::Text("%u", p.frames);
    cell(p.traceMs.value(), "%.2f");
    cell(p.reorderMs.value(), "%.2f");
    cell(p.frameMs.value(), "%.2f");
    cell(p.predictionError.value(), "%.4f");
    cell(p.cellHitRate.value(), "%.1f%%", 100.0);
    cell(p.warpEfficiency.value(), "%.1f%%", 100.0);
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
      lines.push_back({x, p.label});
      if (y < 0.0) continue;  // the line is the baseline: no point in the "no value" strip
    }
    points.push_back({x, y, std::to_string(p.number), std::to_string(p.number) + " " + p.label, &p == current});
  }
  const ScatterAxes axes{kXAxes[view.xAxis], kYTitles[view.yAxis],
                         view.yAxis == 2 ? "n/a: not measured (detailed stats off, or the rt tracer)"
                                         : "n/a: no prediction (a baseline, or a key with no end point)"};
  drawScatter("speed-accuracy", points, lines, axes, height);
  if (!hidden.empty()) ImGui::TextDisabled("not on this axis (no trace stage): %s", hidden.c_str());
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
  const float half = 0.5f * ImGui::GetContentRegionAvail().x - ImGui::CalcTextSize("x").x - 12.0f;
  ImGui::SetNextItemWidth(half);
  ImGui::Combo("x", &view.xAxis, kXAxes, IM_ARRAYSIZE(kXAxes));
  ImGui::SameLine();
  ImGui::SetNextItemWidth(half);
  ImGui::Combo("y", &view.yAxis, kYAxes, IM_ARRAYSIZE(kYAxes));
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", kYHelp[view.yAxis]);
  const float avail = ImGui::GetContentRegionAvail().y;
  const float plotHeight = std::max(120.0f, 0.6f * avail - ImGui::GetTextLineHeightWithSpacing());
  drawPlot(book, view, plotHeight);
  drawTable(book, std::max(3.0f * ImGui::GetFrameHeight(), ImGui::GetContentRegionAvail().y));
  ImGui::End();
}

}  // namespace raylab
