#include "ui/timing_panel.h"

#include <algorithm>
#include <cstdio>
#include <map>

#include <imgui.h>

#include "ui/panel_layout.h"
#include "ui/stage_colors.h"

namespace raylab {
namespace {

std::string formatBytes(uint64_t bytes) {
  char text[32];
  if (bytes >= (1ull << 30)) std::snprintf(text, sizeof(text), "%.2f GiB", bytes / double(1ull << 30));
  else if (bytes >= (1ull << 20)) std::snprintf(text, sizeof(text), "%.2f MiB", bytes / double(1ull << 20));
  else std::snprintf(text, sizeof(text), "%.1f KiB", bytes / 1024.0);
  return text;
}

std::string percent(double v) {
  if (v < 0.0) return "n/a";  // not measured: the one way the screen says so
  char text[16];
  std::snprintf(text, sizeof(text), "%.1f%%", 100.0 * v);
  return text;
}

void plot(const char* label, const std::vector<float>& values, ImU32 color, float height) {
  if (values.empty()) return;
  float hi = *std::max_element(values.begin(), values.end());
  char overlay[48];
  std::snprintf(overlay, sizeof(overlay), "%s %.2f ms", label, values.back());
  ImGui::PushStyleColor(ImGuiCol_PlotLines, color);
  ImGui::PlotLines((std::string("##") + label).c_str(), values.data(), static_cast<int>(values.size()), 0, overlay,
                   0.0f, hi > 0.0f ? hi * 1.1f : 1.0f, ImVec2(ImGui::GetContentRegionAvail().x, height));
  ImGui::PopStyleColor();
}

void drawHistory(const TimingHistory& history) {
  plot("frame (GPU)", history.frameMs(), IM_COL32(255, 255, 255, 255), 40);
  plot("frame (wall)", history.wallMs(), IM_COL32(180, 180, 180, 255), 20);
  for (const std::string& stage : history.stages()) plot(stage.c_str(), history.stageMs(stage), stageColor(stage), 20);
}

// Per row (a bounce, or the stages outside the bounce loop) the stages' times laid end to end, on one
// scale for all rows, so the bar lengths compare bounces and the segments show where each one's time goes.
void drawStackedBars(const FrameStats& stats) {
  std::map<int, std::vector<const StageTime*>> rows;
  for (const StageTime& t : stats.stages) rows[t.bounce].push_back(&t);
  double longest = 0.0;
  for (const auto& [bounce, stages] : rows) {
    double sum = 0.0;
    for (const StageTime* t : stages) sum += t->ms;
    longest = std::max(longest, sum);
  }
  if (longest <= 0.0) {
    ImGui::TextDisabled("no stage times (timestamps unsupported?)");
    return;
  }
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const float labelWidth = 70.0f, height = ImGui::GetTextLineHeight();
  // The bar leaves room for its time after it ("1234.56 ms"): a fixed 60 px ran 2 px past the panel.
  const float timeWidth = ImGui::CalcTextSize("0000.00 ms").x + ImGui::GetStyle().ItemSpacing.x;
  const float barWidth = std::max(50.0f, ImGui::GetContentRegionAvail().x - labelWidth - timeWidth);
  for (const auto& [bounce, stages] : rows) {
    ImGui::Text("%s", bounce < 0 ? "frame" : ("bounce " + std::to_string(bounce)).c_str());
    ImGui::SameLine(labelWidth);
    ImVec2 p = ImGui::GetCursorScreenPos();
    double sum = 0.0;
    for (const StageTime* t : stages) {
      float x0 = p.x + static_cast<float>(sum / longest) * barWidth;
      sum += t->ms;
      float x1 = p.x + static_cast<float>(sum / longest) * barWidth;
      draw->AddRectFilled(ImVec2(x0, p.y), ImVec2(std::max(x1, x0 + 1.0f), p.y + height), stageColor(t->stage));
      if (ImGui::IsMouseHoveringRect(ImVec2(x0, p.y), ImVec2(x1, p.y + height)))
        ImGui::SetTooltip("%s: %.3f ms", t->stage.c_str(), t->ms);
    }
    ImGui::Dummy(ImVec2(barWidth, height));
    ImGui::SameLine();
    ImGui::Text("%.2f ms", sum);
  }
  // What no stage covers, on the same scale: the bars above and this one add up to the GPU frame time.
  const double rest = stats.unattributedMs();
  ImGui::Text("unattrib.");
  ImGui::SameLine(labelWidth);
  ImVec2 p = ImGui::GetCursorScreenPos();
  float x1 = p.x + static_cast<float>(std::min(1.0, rest / longest)) * barWidth;
  draw->AddRectFilled(p, ImVec2(std::max(x1, p.x + 1.0f), p.y + height), stageColor("unattributed"));
  ImGui::Dummy(ImVec2(barWidth, height));
  // Where that time goes: the frame's fixed costs (FrameStats::commands, issue 36).
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("GPU frame time outside every stage (barriers, driver work); the frame issued %u dispatches "
                      "(%u indirect), %u barriers, %u indirect-size writes in %u submissions",
                      stats.commands.dispatches(), stats.commands.indirectDispatches, stats.commands.barriers,
                      stats.commands.sizeWrites, stats.submissions);
  ImGui::SameLine();
  ImGui::Text("%.2f ms", rest);
}

// What each colour of the bars is: the stages of this frame in their order, wrapped to the panel's width.
void drawStageLegend(const FrameStats& stats) {
  std::vector<std::string> seen;
  for (const StageTime& t : stats.stages)
    if (std::find(seen.begin(), seen.end(), t.stage) == seen.end()) seen.push_back(t.stage);
  if (seen.empty()) return;
  seen.push_back("unattributed");
  const float box = ImGui::GetTextLineHeight(), spacing = ImGui::GetStyle().ItemSpacing.x;
  float right = ImGui::GetContentRegionAvail().x;
  float used = 0.0f;
  for (size_t i = 0; i < seen.size(); ++i) {
    const float width = box + 4.0f + ImGui::CalcTextSize(seen[i].c_str()).x;
    if (i > 0 && used + spacing + width <= right) ImGui::SameLine(), used += spacing;
    else used = 0.0f;
    used += width;
    ImVec2 p = ImGui::GetCursorScreenPos();
    ImGui::GetWindowDrawList()->AddRectFilled(p, ImVec2(p.x + box, p.y + box), stageColor(seen[i]));
    ImGui::Dummy(ImVec2(box, box));
    ImGui::SameLine(0.0f, 4.0f);
    ImGui::TextUnformatted(seen[i].c_str());
  }
}

// Mean, min and max of the last frames (one frame's number jumps too much to read on a CPU device).
struct Window {
  double mean = 0.0, lo = 0.0, hi = 0.0;
};
Window lastFrames(const std::vector<float>& v, size_t n) {
  Window w;
  if (v.empty()) return w;
  size_t from = v.size() > n ? v.size() - n : 0;
  w.lo = w.hi = v[from];
  for (size_t i = from; i < v.size(); ++i) w.mean += v[i], w.lo = std::min<double>(w.lo, v[i]), w.hi = std::max<double>(w.hi, v[i]);
  w.mean /= double(v.size() - from);
  return w;
}

void drawBounceTable(const FrameStats& stats) {
  if (!ImGui::BeginTable("bounces", 6, ImGuiTableFlags_Borders | ImGuiTableFlags_SizingFixedFit)) return;
  for (const char* h : {"bounce", "rays", "SIMT", "virtual warp", "steps", "sorted after (why)"}) ImGui::TableSetupColumn(h);
  ImGui::TableHeadersRow();
  for (size_t b = 0; b < stats.bounces.size(); ++b) {
    const BounceStats& s = stats.bounces[b];
    ImGui::TableNextRow();
    ImGui::TableNextColumn(), ImGui::Text("%zu", b);
    ImGui::TableNextColumn(), ImGui::Text("%u", s.rays);
    ImGui::TableNextColumn(), ImGui::TextUnformatted(percent(s.simtEfficiency).c_str());
    ImGui::TableNextColumn(), ImGui::TextUnformatted(percent(s.virtualWarpEfficiency).c_str());
    ImGui::TableNextColumn();
    if (s.meanTraversalSteps >= 0.0) ImGui::Text("%.1f", s.meanTraversalSteps); else ImGui::TextDisabled("n/a");
    ImGui::TableNextColumn();
    if (!s.sortReason.empty()) ImGui::Text("%s (%s)", s.sortedAfter ? "yes" : "no", s.sortReason.c_str());
  }
  ImGui::EndTable();
}

void drawMemory(const FrameStats& s) {
  if (s.lengthCacheOccupancy >= 0.0)
    ImGui::Text("length cache %s (%.1f%% occupied)", formatBytes(s.lengthCacheBytes).c_str(), 100.0 * s.lengthCacheOccupancy);
  else
    ImGui::Text("length cache %s (occupancy n/a)", formatBytes(s.lengthCacheBytes).c_str());
  if (s.lengthCacheResets >= 0)
    ImGui::Text("length cache resets this frame: %lld", static_cast<long long>(s.lengthCacheResets));
  ImGui::Text("sort scratch %s, path state %s", formatBytes(s.sortScratchBytes).c_str(), formatBytes(s.pathStateBytes).c_str());
  ImGui::Text("scene %s, key bits %u", formatBytes(s.sceneBytes).c_str(), s.keyBits);
}

}  // namespace

void drawTimingPanel(const TimingHistory& history, const FrameStats& stats, Settings& settings, ViewOptions& view) {
  if (!ImGui::Begin(panelTitle(Panel::Timing))) {
    ImGui::End();
    return;
  }
  constexpr size_t kAveraged = 30;
  const Window gpu = lastFrames(history.frameMs(), kAveraged), wall = lastFrames(history.wallMs(), kAveraged);
  const size_t n = std::min(history.size(), kAveraged);
  ImGui::TextWrapped("GPU %.2f ms (%.2f..%.2f), wall %.2f ms", gpu.mean, gpu.lo, gpu.hi, wall.mean);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("mean (min..max) of the last %zu frames", n);
  // Rays and time of the same (last) frame; wrapped, as a narrow panel cut "...rays/s; 53 sp".
  ImGui::TextWrapped("last frame %.2f ms GPU: %.3g rays/s; %u spp", stats.frameMs, stats.raysPerSecond, stats.samplesPerPixel);
  // One line whether or not a stage is over the render budget, the whole note on hover: the note came and
  // went frame by frame and moved everything under it by two lines.
  const float fps = view.uiFrameMs > 0.0f ? 1000.0f / view.uiFrameMs : 0.0f;
  if (!view.slowStageNote.empty()) {
    ImGui::TextColored(ImVec4(1.0f, 0.75f, 0.3f, 1.0f), "UI %.1f fps: a stage is over budget (hover)", fps);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", view.slowStageNote.c_str());
  } else {
    ImGui::Text("UI %.1f fps: every stage fits the budget", fps);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("the window's own frame rate; render work is split to fit --render-budget-ms");
  }
  ImGui::Checkbox("detailed stats", &view.detailedStats);
  ImGui::SameLine();
  ImGui::Checkbox("count SIMT lanes", &settings.countSimt);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("subgroup ballots in traversal: slower, not for timing");
  if (ImGui::CollapsingHeader("Stages per bounce", ImGuiTreeNodeFlags_DefaultOpen)) {
    drawStackedBars(stats);
    drawStageLegend(stats);
  }
  if (ImGui::CollapsingHeader("History (ms per frame)", ImGuiTreeNodeFlags_DefaultOpen)) drawHistory(history);
  if (ImGui::CollapsingHeader("Coherence", ImGuiTreeNodeFlags_DefaultOpen)) drawBounceTable(stats);
  if (ImGui::CollapsingHeader("Memory")) drawMemory(stats);
  ImGui::End();
}

}  // namespace raylab
