#include "app/window/heatmap_hover.h"

#include <algorithm>
#include <cmath>

#include <imgui.h>

#include "renderer/heatmap/heatmap_pass.h"
#include "renderer/path_tracer.h"

namespace raylab {

void updateHeatmapHover(PathTracer& tracer, bool heatmapShown) {
  const ImGuiIO& io = ImGui::GetIO();
  const bool overImage = heatmapShown && !io.WantCaptureMouse && ImGui::IsMousePosValid(&io.MousePos) &&
                         io.DisplaySize.x > 0 && io.DisplaySize.y > 0 && io.MousePos.x >= 0 && io.MousePos.y >= 0 &&
                         io.MousePos.x < io.DisplaySize.x && io.MousePos.y < io.DisplaySize.y;
  if (!overImage) {
    tracer.heatmap().setProbe(std::nullopt);
    return;
  }
  auto pixel = [](float mouse, float display, uint32_t size) {
    return std::min(size - 1, static_cast<uint32_t>(std::floor(mouse / display * float(size))));
  };
  tracer.heatmap().setProbe(glm::uvec2(pixel(io.MousePos.x, io.DisplaySize.x, tracer.width()),
                                       pixel(io.MousePos.y, io.DisplaySize.y, tracer.height())));
}

}  // namespace raylab
