#include "ui/help_overlay.h"

#include <imgui.h>

namespace raylab {

void drawHelpOverlay(bool* open) {
  if (!*open) return;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowBgAlpha(0.9f);
  if (ImGui::Begin("Help (F1)", open, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings)) {
    static const char* const kLines[][2] = {
        {"right mouse + move", "look around (fly) / turn around the pivot (orbit)"},
        {"W A S D", "move forward, left, back, right (orbit: zoom and turn)"},
        {"Q E", "down, up (orbit: turn)"},
        {"Shift", "move faster"},
        {"mouse wheel", "dolly (orbit: zoom) over the render; scrolls a panel under the pointer"},
        {"O", "toggle orbit mode around the target"},
        {"R", "reset the camera to the current viewpoint"},
        {"L", "restart learning: a fresh length cache and accumulation, as a re-render of a screenshot has"},
        {"K", "record a camera path; again: stop and save it beside the screenshots (replay: --camera-path)"},
        {"P", "play the camera path (--camera-path, else the last recorded) one frame per render frame; stop"},
        {"F12", "save the render as PNG + JSON sidecar"},
        {"Shift+F12", "save the whole window with the panels"},
        {"Tab", "hide or show the panels"},
        {"F1", "this help"},
        {"Esc", "close this help"},
    };
    if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_SizingFixedFit)) {
      for (const auto& line : kLines) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn(), ImGui::TextUnformatted(line[0]);
        ImGui::TableNextColumn(), ImGui::TextUnformatted(line[1]);
      }
      ImGui::EndTable();
    }
    ImGui::Separator();
    ImGui::TextWrapped("Accumulation restarts when the image changes (scene, camera, size, bounces, samples);\n"
                       "key strategy, sort and grid never change the image, only its cost.");
  }
  ImGui::End();
}

}  // namespace raylab
