// imgui.ini keeps, besides the panels' layout, the last Settings (as toJson(Settings)), the view options
// and the window size, through an ImGui settings handler: the lab reopens as it was left.
#pragma once

#include <optional>

#include "renderer/settings/settings.h"
#include "ui/ui_state.h"

namespace raylab {

struct IniState {
  // Read: what the file held (absent fields stay unset).
  std::optional<Settings> loadedSettings;
  std::optional<float> loadedScale;
  std::optional<bool> loadedDetailed;
  int loadedWidth = 0, loadedHeight = 0;
  // Written at every save: the window points these at its live state.
  const Settings* settings = nullptr;
  const ViewOptions* view = nullptr;
  int width = 0, height = 0;
};

// Registers the "[Raylab][State]" section with the current ImGui context; `state` must outlive it.
void installIniHandler(IniState* state);

}  // namespace raylab
