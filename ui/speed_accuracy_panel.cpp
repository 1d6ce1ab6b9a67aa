#include "ui/speed_accuracy_panel.h"

#include <algorithm>

#include <imgui.h>

#include "ui/scatter_plot.h"

namespace raylab {
namespace {

void cell(double v, const char* format) {
  ImGui::TableNextColumn();
  if (v < 0.0) ImGui::TextDisabled("-");
  else ImGui::Text(format, v);
}

void drawTable(const SpeedAccuracyBook& book, const Settings& settings) {
  if (!ImGui::BeginTable("points", 7, ImGuiTableFlags_Borders | ImGuiTableFlags_SizingFixedFit)) return;
  for (const char* h : {"strategy", "sort", "trace ms", "reorder ms", "frame ms", "error", "cell hit"})
    ImGui::TableSetupColumn(h);
  ImGui::TableHeadersRow();
  for (const StrategyPoint& p : book.points()) {
    ImGui::TableNextRow();
    if (p.strategy == settings.strategy)
      ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg0, IM_COL32(90, 75, 20, 255));
    ImGui::TableNextColumn(), ImGui::TextUnformatted(toString(p.strategy).c_str());
    ImGui::TableNextColumn(), ImGui::TextUnformatted(toString(p.sort).c_str());
    cell(p.traceMs, "%.2f");
    cell(p.reorderMs, "%.2f");
    cell(p.frameMs, "%.2f");
    cell(p.meanError, "%.4f");
    cell(p.cellHitRate < 0.0 ? -1.0 : 100.0 * p.cellHitRate, "%.1f%%");
  }
  ImGui::EndTable();
}

std::vector<ScatterPoint> scatter(const SpeedAccuracyBook& book, const Settings& settings, bool frameTime) {
  std::vector<ScatterPoint> points;
  for (const StrategyPoint& p : book.points()) {
    if (p.cellHitRate < 0.0) continue;
    points.push_back({frameTime ? p.frameMs : p.traceMs, p.cellHitRate, toString(p.strategy), p.strategy == settings.strategy});
  }
  return points;
}

}  // namespace

void drawSpeedAccuracyPanel(const SpeedAccuracyBook& book, const Settings& settings) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x - 370, 450), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(360, std::max(100.0f, display.y - 460)), ImGuiCond_FirstUseEver);
  if (!ImGui::Begin("Speed vs accuracy")) {
    ImGui::End();
    return;
  }
  const StrategyPoint* current = book.find(settings.strategy);
  if (!current || current->cellHitRate < 0.0)
    ImGui::TextWrapped("%s: no prediction accuracy (needs a spatial key, sorting and detailed stats)",
                       toString(settings.strategy).c_str());
  if (ImGui::BeginTabBar("views")) {
    const float plotHeight = std::max(80.0f, ImGui::GetContentRegionAvail().y - ImGui::GetFrameHeightWithSpacing());
    if (ImGui::BeginTabItem("vs trace time")) {
      drawScatter("trace", scatter(book, settings, false), "trace ms", "cell hit rate", 1.0, plotHeight);
      ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("vs frame time")) {
      drawScatter("frame", scatter(book, settings, true), "frame ms", "cell hit rate", 1.0, plotHeight);
      ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("table")) {
      drawTable(book, settings);
      ImGui::EndTabItem();
    }
    ImGui::EndTabBar();
  }
  ImGui::End();
}

}  // namespace raylab
