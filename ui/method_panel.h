// The method panel: everything about how rays are reordered, as edits of Settings (and the resolution
// scale of the view). Every slider is clamped to the range where the method is defined (its row of the
// settings table, renderer/settings/settings_table.h).
#pragma once

#include "renderer/settings/settings.h"
#include "ui/ui_state.h"

namespace raylab {

void drawMethodPanel(Settings& settings, ViewOptions& view);

// Settings{} for the method, keeping what the window owns (scene, viewpoint, render size).
Settings methodDefaults(const Settings& current);

}  // namespace raylab
