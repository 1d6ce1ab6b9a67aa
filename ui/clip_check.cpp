#include "ui/clip_check.h"

#include <algorithm>

#include <imgui.h>
#include <imgui_internal.h>

namespace raylab {
namespace {

// The panel being drawn: one at a time, on the UI thread.
std::vector<std::string>& pending() {
  static std::vector<std::string> items;
  return items;
}

}  // namespace

void startClipReport() { pending().clear(); }

ClipReport finishClipReport(const char* title) {
  ClipReport report;
  report.items.swap(pending());
  ImGuiWindow* window = ImGui::FindWindowByName(title);
  if (!window || !window->Active || window->Collapsed) return report;
  // A pixel of slack: ImGui rounds positions.
  report.hiddenWidth = std::max(0.0f, window->DC.CursorMaxPos.x - window->WorkRect.Max.x - 1.0f);
  for (ImGuiWindow* child : window->DC.ChildWindows)
    if (child->Active) report.hiddenWidth = std::max(report.hiddenWidth, child->ScrollMax.x);
  return report;
}

bool fitsCombo(const char* preview) {
  const ImGuiStyle& style = ImGui::GetStyle();
  // The box holds the preview text, its padding and the arrow button (a frame-height square).
  const float room = ImGui::CalcItemWidth() - ImGui::GetFrameHeight() - 2.0f * style.FramePadding.x;
  const bool fits = ImGui::CalcTextSize(preview).x <= room + 0.5f;
  if (!fits) pending().push_back(preview);
  return fits;
}

}  // namespace raylab
