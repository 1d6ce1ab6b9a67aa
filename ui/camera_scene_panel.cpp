#include "ui/camera_scene_panel.h"

#include <algorithm>

#include <cstring>

#include <imgui.h>

#include "ui/camera_path_section.h"
#include "ui/panel_layout.h"

namespace raylab {
namespace {

void errorText(const std::string& text) {
  if (text.empty()) return;
  ImGui::PushStyleColor(ImGuiCol_Text, IM_COL32(255, 110, 100, 255));
  ImGui::TextWrapped("%s", text.c_str());
  ImGui::PopStyleColor();
}

void drawScene(const CameraModel& m, UiRequests& r) {
  if (ImGui::BeginCombo("scene", m.scene.c_str())) {
    for (const std::string& name : m.builtinScenes)
      if (ImGui::Selectable(name.c_str(), name == m.scene)) r.loadScene = name;
    ImGui::EndCombo();
  }
  static char path[512] = "";
  // The field takes what the button leaves of the row, so the hint shows whole at any panel width.
  ImGui::SetNextItemWidth(std::max(60.0f, ImGui::GetContentRegionAvail().x - ImGui::CalcTextSize("Open glTF").x -
                                               2.0f * ImGui::GetStyle().FramePadding.x - ImGui::GetStyle().ItemSpacing.x));
  bool enter = ImGui::InputTextWithHint("##gltf", "scene.gltf or .glb path", path, sizeof(path),
                                        ImGuiInputTextFlags_EnterReturnsTrue);
  ImGui::SameLine();
  if ((ImGui::Button("Open glTF") || enter) && std::strlen(path) > 0) r.loadScene = std::string(path);
  errorText(m.sceneError);
  // Sponza alone skips about a hundred texture files: a folded list, not a wall of text.
  if (!m.loadWarnings.empty()) {
    std::string header = std::to_string(m.loadWarnings.size()) + " load warning" +
                         (m.loadWarnings.size() == 1 ? "" : "s") + "###loadwarnings";
    if (ImGui::CollapsingHeader(header.c_str())) {
      ImGui::BeginChild("warnings", ImVec2(0, 120), true, ImGuiWindowFlags_HorizontalScrollbar);
      for (const std::string& w : m.loadWarnings) ImGui::TextUnformatted(w.c_str());
      ImGui::EndChild();
    }
  }
}

// Like the load warnings, a folded list with its count; open and red, because what failed is lost.
void drawWriteFailures(const CameraModel& m) {
  if (m.writeFailures.empty()) return;
  std::string header = std::to_string(m.writeFailures.size()) + " failed write" + (m.writeFailures.size() == 1 ? "" : "s") +
                       "###writefailures";
  if (!ImGui::CollapsingHeader(header.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) return;
  ImGui::BeginChild("write failures", ImVec2(0, 80), true, ImGuiWindowFlags_HorizontalScrollbar);
  for (const std::string& f : m.writeFailures) errorText(f);
  ImGui::EndChild();
}

void drawViewpoints(const CameraModel& m, UiRequests& r) {
  for (size_t i = 0; i < m.viewpoints.size(); ++i) {
    if (i > 0 && ImGui::GetContentRegionAvail().x > ImGui::CalcTextSize(m.viewpoints[i].c_str()).x + 20) ImGui::SameLine();
    if (ImGui::Button(m.viewpoints[i].c_str())) r.view = m.viewpoints[i];
  }
}

void drawCamera(const CameraModel& m, UiRequests& r) {
  bool orbit = m.orbit;
  if (ImGui::Checkbox("orbit", &orbit)) r.orbit = orbit;
  ImGui::SameLine();
  float speed = m.speed;
  ImGui::SetNextItemWidth(120);
  if (ImGui::SliderFloat("speed", &speed, 1e-3f, 1e4f, "%.3g", ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp))
    r.speed = speed;
  ImGui::TextWrapped("%s", m.cameraShortText.c_str());
  if (ImGui::Button("Copy camera")) ImGui::SetClipboardText(m.cameraText.c_str());
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("copies the exact figures (the line above is rounded)");
  ImGui::SameLine();
  if (ImGui::Button("Paste camera")) {
    const char* clip = ImGui::GetClipboardText();
    r.cameraText = clip ? std::string(clip) : std::string();
  }
  static char typed[256] = "";
  ImGui::SetNextItemWidth(-1.0f);  // the whole row: the hint is the format to type
  if (ImGui::InputTextWithHint("##camera", "x y z tx ty tz [fov deg]", typed, sizeof(typed),
                               ImGuiInputTextFlags_EnterReturnsTrue))
    r.cameraText = std::string(typed);
  errorText(m.cameraError);
}

void drawCapture(const CameraModel& m, UiRequests& r) {
  ImGui::TextWrapped("folder: %s", m.screenshotDir.c_str());
  if (ImGui::Button("Save render (F12)")) r.screenshotRender = true;
  // Beside it where the row has room, else below (a narrow panel cut the second button).
  const char* window = "Save window (Shift+F12)";
  const float need = ImGui::CalcTextSize(window).x + 2.0f * ImGui::GetStyle().FramePadding.x + ImGui::GetStyle().ItemSpacing.x;
  if (ImGui::GetContentRegionAvail().x - ImGui::GetItemRectSize().x >= need) ImGui::SameLine();
  if (ImGui::Button(window)) r.screenshotWindow = true;
  if (!m.lastScreenshot.empty()) ImGui::TextWrapped("%s", m.lastScreenshot.c_str());
}

void drawWindowSection(UiRequests& r) {
  if (ImGui::Button("Reset layout")) r.resetLayout = true;
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("put the panels back where they open (as --reset does at start)");
}

}  // namespace

UiRequests drawCameraScenePanel(const CameraModel& m) {
  UiRequests r;
  if (!ImGui::Begin(panelTitle(Panel::SceneCamera))) {
    ImGui::End();
    return r;
  }
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
  ImGui::TextWrapped("%s", m.deviceName.c_str());  // long names (llvmpipe's) wrap rather than run out
  ImGui::PopStyleColor();
  drawWriteFailures(m);
  // Screenshots first: at 1280x720 they sat below the fold, under the scene and camera sections.
  if (ImGui::CollapsingHeader("Screenshots", ImGuiTreeNodeFlags_DefaultOpen)) drawCapture(m, r);
  if (ImGui::CollapsingHeader("Camera path", ImGuiTreeNodeFlags_DefaultOpen)) drawCameraPathSection(m.path, r);
  if (ImGui::CollapsingHeader("Scene", ImGuiTreeNodeFlags_DefaultOpen)) drawScene(m, r);
  if (ImGui::CollapsingHeader("Viewpoints", ImGuiTreeNodeFlags_DefaultOpen)) drawViewpoints(m, r);
  if (ImGui::CollapsingHeader("Camera", ImGuiTreeNodeFlags_DefaultOpen)) drawCamera(m, r);
  if (ImGui::CollapsingHeader("Window", ImGuiTreeNodeFlags_DefaultOpen)) drawWindowSection(r);
  ImGui::End();
  return r;
}

}  // namespace raylab
