#include "ui/camera_path_section.h"

#include <imgui.h>

namespace raylab {

void drawCameraPathSection(const CameraPathModel& m, UiRequests& r) {
  ImGui::BeginDisabled(m.spec.empty() && !m.playing);
  if (ImGui::Button(m.playing ? "Stop (P)" : "Play (P)")) r.togglePathPlayback = true;
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip("one path frame per render frame, the accumulation restarting each, as `raylab render "
                      "--camera-path` replays it");
  ImGui::SameLine();
  if (m.playing)
    ImGui::Text("frame %u / %u", m.frame, m.frames);
  else
    ImGui::TextWrapped("%s", m.spec.empty() ? "no path (--camera-path, or record one)" : m.spec.c_str());
  // Red while recording: every UI frame adds a keyframe.
  if (m.recording) ImGui::PushStyleColor(ImGuiCol_Button, IM_COL32(190, 40, 40, 255));
  if (ImGui::Button(m.recording ? "Stop and save (K)" : "Record (K)")) r.togglePathRecording = true;
  if (m.recording) ImGui::PopStyleColor();
  if (m.recording) {
    ImGui::SameLine();
    ImGui::Text("%u keyframes", m.recordedFrames);
  }
  if (!m.status.empty()) ImGui::TextWrapped("%s", m.status.c_str());
}

}  // namespace raylab
