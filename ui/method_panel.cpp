#include "ui/method_panel.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <imgui.h>

#include "renderer/heatmap/heatmap_rules.h"
#include "renderer/reorder/key_strategies.h"
#include "renderer/settings/settings_table.h"
#include "ui/clip_check.h"
#include "ui/panel_layout.h"

namespace raylab {
namespace {

constexpr ImGuiSliderFlags kClamp = ImGuiSliderFlags_AlwaysClamp;
constexpr ImGuiSliderFlags kLog = ImGuiSliderFlags_AlwaysClamp | ImGuiSliderFlags_Logarithmic;

template <class E>
bool comboEnum(const char* label, E& value, const std::vector<E>& all) {
  bool changed = false;
  fitsCombo(toString(value).c_str());
  if (ImGui::BeginCombo(label, toString(value).c_str())) {
    for (E e : all) {
      if (ImGui::Selectable(toString(e).c_str(), e == value)) value = e, changed = true;
      if (e == value) ImGui::SetItemDefaultFocus();
    }
    ImGui::EndCombo();
  }
  return changed;
}

// A combo over one Settings field whose values that would not go with the rest (settingsError) are greyed
// out, with the reason as tooltip.
template <class E>
void comboSetting(const char* label, Settings& s, E Settings::*field, const std::vector<E>& all) {
  fitsCombo(toString(s.*field).c_str());
  if (!ImGui::BeginCombo(label, toString(s.*field).c_str())) return;
  for (E e : all) {
    Settings candidate = s;
    candidate.*field = e;
    std::optional<std::string> why = settingsError(candidate);
    ImGui::BeginDisabled(why.has_value() && e != s.*field);
    if (ImGui::Selectable(toString(e).c_str(), e == s.*field)) s.*field = e;
    ImGui::EndDisabled();
    if (why && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) ImGui::SetTooltip("%s", why->c_str());
    if (e == s.*field) ImGui::SetItemDefaultFocus();
  }
  ImGui::EndCombo();
}

bool sliderU32(const char* label, uint32_t& v, uint32_t lo, uint32_t hi, ImGuiSliderFlags flags = kClamp) {
  int i = static_cast<int>(v);
  bool changed = ImGui::SliderInt(label, &i, static_cast<int>(lo), static_cast<int>(hi), "%d", flags);
  if (changed) v = static_cast<uint32_t>(i);
  return changed;
}

// Sliders over a setting's range, as its row of the settings table declares it.
bool sliderSetting(const char* label, uint32_t& v, const char* flag, ImGuiSliderFlags flags = kClamp) {
  const NumberRange r = settingRange(flag);
  return sliderU32(label, v, static_cast<uint32_t>(r.lo), static_cast<uint32_t>(r.hi), flags);
}
bool sliderSetting(const char* label, float& v, const char* flag, const char* format, ImGuiSliderFlags flags = kClamp) {
  const NumberRange r = settingRange(flag);
  return ImGui::SliderFloat(label, &v, static_cast<float>(r.lo), static_cast<float>(r.hi), format, flags);
}

// A control the device cannot offer: one disabled line, why in the tooltip.
void unavailableLine(const char* text, const std::string& why) {
  ImGui::TextDisabled("%s", text);
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) ImGui::SetTooltip("%s", why.c_str());
}

// A line and a greyed title between the sections of one tab (ImGui 1.86, Debian 12's, has no SeparatorText).
void sectionTitle(const char* title) {
  ImGui::Separator();
  ImGui::TextDisabled("%s", title);
}

void drawSortSection(Settings& s) {
  comboSetting("strategy", s, &Settings::strategy, allKeyStrategies());
  // Strategy none makes no keys: the sort and its parameters apply to nothing, so they are dimmed.
  ImGui::BeginDisabled(s.strategy == KeyStrategy::None);
  comboSetting("sort", s, &Settings::sort, allValues<SortAlgorithm>());
  comboEnum("sort policy", s.sortPolicy, allValues<SortPolicy>());
  sliderSetting("sorted key bits", s.sortBits, "sort-bits");
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("order only the key's top bits (0: all); 8 fewer is one radix pass less");
}

// How the frame is traced and shaded, and what it renders.
void drawPipelineSection(Settings& s, ViewOptions& view) {
  comboSetting("fusion", s, &Settings::fusion, allValues<Fusion>());
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("keys: made in shade; gather: the reorder done by the next trace (compute wavefront only)");
  if (s.fusion != Fusion::None && s.sorts() && !s.fusesKeys() && !s.fusesGather())
    ImGui::TextDisabled("fusion: the rt tracer keeps separate passes");
  comboSetting("compaction", s, &Settings::compaction, allValues<Compaction>());
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("shade packs the live paths at the front, so later stages visit only live paths (compute wavefront only)");
  if (s.compaction != Compaction::None && !s.compacts())
    ImGui::TextDisabled("compaction: only the compute wavefront compacts");
  comboSetting("trace-shade", s, &Settings::traceShade, allValues<TraceShade>());
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("fused: one dispatch per bounce where nothing reads the hit in between (compute wavefront)");
  comboSetting("kernel", s, &Settings::kernel, allValues<Kernel>());
  if (s.kernel == Kernel::Megakernel) ImGui::TextDisabled("the megakernel never sorts");
  // The rt tracer and SER need extensions the device may lack: then each is one greyed line, the reason (a
  // paragraph of missing extensions) on hover, so the controls below stay in view.
  if (!view.rtUnavailable.empty()) {
    unavailableLine(("tracer: " + toString(s.tracer) + " (rt unavailable)").c_str(), view.rtUnavailable);
  } else {
    comboSetting("tracer", s, &Settings::tracer, allValues<Tracer>());
  }
  // The layout the compute tracer walks; the rt tracer keeps the setting but has its own structure.
  ImGui::BeginDisabled(s.tracer != Tracer::Compute);
  comboSetting("BVH", s, &Settings::bvh, allValues<BvhLayout>());
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip("binary, or compressed 8-wide (quantized child boxes, as CWBVH); a new image (compute tracer only)");
  if (!view.serUnavailable.empty()) {
    unavailableLine(("SER: " + toString(s.ser) + " (unavailable)").c_str(), view.serUnavailable);
  } else {
    ImGui::BeginDisabled(s.tracer != Tracer::Rt || s.kernel != Kernel::Megakernel);
    comboEnum("SER", s.ser, allValues<Ser>());
    ImGui::EndDisabled();
    if (s.ser == Ser::Hint) ImGui::TextDisabled("hint: top bits of the strategy's key");
  }
  ImGui::Separator();
  sliderSetting("bounces", s.bounces, "bounces");
  sliderSetting("samples per frame", s.sppPerFrame, "spp", kLog);
  ImGui::SliderFloat("resolution scale", &view.resolutionScale, ViewOptions::kMinScale, ViewOptions::kMaxScale, "%.2f", kClamp);
  ImGui::SliderFloat("exposure", &s.exposure, 0.01f, 100.0f, "%.2f", kLog);
}

void drawGridSection(Settings& s) {
  ImGui::Checkbox("automatic grid", &s.grid.automatic);
  if (s.grid.automatic) {
    sliderSetting("cells on largest axis", s.grid.autoCells, "grid", kLog);
  } else {
    int cells[3] = {int(s.grid.cells.x), int(s.grid.cells.y), int(s.grid.cells.z)};
    const NumberRange r = settingRange("grid");
    if (ImGui::SliderInt3("cells x y z", cells, int(r.lo), int(r.hi), "%d", kLog))
      s.grid.cells = {uint32_t(cells[0]), uint32_t(cells[1]), uint32_t(cells[2])};
  }
  ImGui::Checkbox("clamp grid to camera", &s.clampToCamera);
  ImGui::BeginDisabled(!s.clampToCamera);
  ImGui::SliderFloat("clamp distance", &s.clampDistance, 0.01f, float(settingRange("clamp").hi), "%.3g", kLog);
  ImGui::EndDisabled();
}

// Parameters of the length estimates; each is greyed out unless the chosen strategy uses it.
void drawLengthSection(Settings& s) {
  const KeyStrategyInfo& k = strategyInfo(s.strategy);
  ImGui::BeginDisabled(!k.readsFixedLength);
  sliderSetting("fixed-length factor", s.fixedFactor, "fixed-factor", "%.3f");
  ImGui::EndDisabled();
  ImGui::BeginDisabled(!k.readsEmaAlpha);
  sliderSetting("EMA alpha", s.emaAlpha, "ema-alpha", "%.3f", kLog);
  ImGui::EndDisabled();
  ImGui::BeginDisabled(!k.samplesGaussian);
  bool never = std::isinf(s.gaussReset);
  if (ImGui::Checkbox("never reset", &never)) s.gaussReset = never ? INFINITY : 20.0f;
  ImGui::BeginDisabled(never);
  float reset = never ? 1e6f : s.gaussReset;
  if (ImGui::SliderFloat("reset variance", &reset, 0.001f, 1e6f, "%.4g", kLog) && !never) s.gaussReset = reset;
  ImGui::EndDisabled();
  sliderSetting("outlier sigmas", s.gaussOutlier, "gauss-outlier", "%.2f");
  ImGui::EndDisabled();
  ImGui::BeginDisabled(!k.learnsLengths);
  sliderSetting("learn from 1 ray in", s.learnEvery, "learn-every");
  ImGui::EndDisabled();
}

// Views these settings cannot show are greyed out with the reason as tooltip (heatmap_rules.h).
void drawHeatmapCombo(Settings& s) {
  if (!ImGui::BeginCombo("heatmap", toString(s.heatmap).c_str())) return;
  for (HeatmapView v : allHeatmapViews()) {
    std::optional<std::string> why = heatmapUnavailable(s, v);
    ImGui::BeginDisabled(why.has_value());
    if (ImGui::Selectable(toString(v).c_str(), v == s.heatmap)) s.heatmap = v;
    ImGui::EndDisabled();
    if (why && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) ImGui::SetTooltip("%s", why->c_str());
    if (v == s.heatmap) ImGui::SetItemDefaultFocus();
  }
  ImGui::EndCombo();
}

void drawHeatmapSection(Settings& s) {
  drawHeatmapCombo(s);
  ImGui::BeginDisabled(s.heatmap == HeatmapView::None);
  // The slider shows the bounce drawn, but writes only when moved: fewer bounces must not overwrite the
  // bounce asked for, or raising them again would not bring it back.
  uint32_t bounce = heatmapBounceShown(s);
  if (sliderU32("heatmap bounce", bounce, 0, s.bounces - 1)) s.heatmapBounce = bounce;
  ImGui::EndDisabled();
  // Colouring: keys by cell, rank or hash; scalar views linear or log (range lock: the legend).
  ImGui::BeginDisabled(s.heatmap != HeatmapView::SortKey);
  comboEnum("key colour", s.heatmapKeyColour, allValues<HeatmapKeyColour>());
  ImGui::EndDisabled();
  const bool scalar = s.heatmap == HeatmapView::TraversalSteps || s.heatmap == HeatmapView::WarpEfficiency ||
                      s.heatmap == HeatmapView::CacheMean || s.heatmap == HeatmapView::CacheVariance;
  ImGui::BeginDisabled(!scalar);
  comboEnum("scale", s.heatmapScale, allValues<HeatmapScale>());
  ImGui::EndDisabled();
  // A strategy, sort or kernel change (or a script) can leave the chosen view without data.
  if (std::optional<std::string> why = heatmapUnavailable(s)) ImGui::TextWrapped("showing the render: %s", why->c_str());
}

}  // namespace

Settings methodDefaults(const Settings& current) {
  Settings d;
  d.scene = current.scene;
  d.view = current.view;
  d.width = current.width;
  d.height = current.height;
  return d;
}

void drawMethodPanel(Settings& s, ViewOptions& view) {
  if (!ImGui::Begin(panelTitle(Panel::Method))) {
    ImGui::End();
    return;
  }
  ImGui::PushItemWidth(150);
  // Three tabs: all of the panel's controls in one column at 1280x720 measured 755 px, so the grid, clamp,
  // Gaussian and heatmap controls sat below the fold. The keys' tab (what a reordering study tunes live)
  // opens first and fits the default layout's height.
  if (ImGui::BeginTabBar("method tabs")) {
    if (ImGui::BeginTabItem("Keys")) {
      drawSortSection(s);
      sectionTitle("key grid");
      ImGui::BeginDisabled(!strategyInfo(s.strategy).usesGrid);  // dead-last and none make no cells
      drawGridSection(s);
      ImGui::EndDisabled();
      sectionTitle("length estimates");
      drawLengthSection(s);
      ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("Pipeline")) {
      drawPipelineSection(s, view);
      ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("Heatmap")) {
      drawHeatmapSection(s);
      ImGui::EndTabItem();
    }
    // At the tab bar's right end, not a row of its own below the controls.
    if (ImGui::TabItemButton("Reset", ImGuiTabItemFlags_Trailing)) {
      s = methodDefaults(s);
      view.resolutionScale = view.defaultScale;
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("every method setting back to its default (the scene and view stay)");
    ImGui::EndTabBar();
  }
  ImGui::PopItemWidth();
  ImGui::End();
}

}  // namespace raylab
