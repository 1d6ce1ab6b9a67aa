#include "ui/panel_placement.h"

#include <imgui.h>
#include <imgui_internal.h>

namespace raylab {

void placeNextPanel(Panel panel, bool reset) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const Box b = defaultPanelBox(panel, display.x, display.y);
  const ImGuiCond when = reset ? ImGuiCond_Always : ImGuiCond_FirstUseEver;
  ImGui::SetNextWindowPos(ImVec2(b.x0, b.y0), when);
  ImGui::SetNextWindowSize(ImVec2(b.x1 - b.x0, b.y1 - b.y0), when);
  ImGui::SetNextWindowCollapsed(false, when);
}

bool keepPanelInside(Panel panel, PanelLayout& layout) {
  ImGuiWindow* window = ImGui::FindWindowByName(panelTitle(panel));
  if (!window) return false;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const Box actual{window->Pos.x, window->Pos.y, window->Pos.x + window->Size.x, window->Pos.y + window->Size.y};
  const Box placed = layout.keepInside(panel, actual, window->Collapsed, display.x, display.y, window->ScrollMax.y);
  if (placed.x0 != actual.x0 || placed.y0 != actual.y0) ImGui::SetWindowPos(panelTitle(panel), ImVec2(placed.x0, placed.y0));
  const bool resized = placed.x1 - placed.x0 != actual.x1 - actual.x0 || placed.y1 - placed.y0 != actual.y1 - actual.y0;
  const bool moved = placed.x0 != actual.x0 || placed.y0 != actual.y0;
  if (resized && !window->Collapsed)
    ImGui::SetWindowSize(panelTitle(panel), ImVec2(placed.x1 - placed.x0, placed.y1 - placed.y0));
  return moved || (resized && !window->Collapsed);
}

void recordWindow(const char* title, PanelLayout& layout) {
  ImGuiWindow* window = ImGui::FindWindowByName(title);
  if (!window || !window->Active) return;  // not drawn this frame
  layout.record(title, {window->Pos.x, window->Pos.y, window->Pos.x + window->Size.x, window->Pos.y + window->Size.y},
                window->Collapsed, window->ScrollMax.y);
}

}  // namespace raylab
