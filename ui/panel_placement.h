// PanelLayout applied to the ImGui windows of the panels: their default place before Begin, and after End
// the correction that keeps them inside the display.
#pragma once

#include "ui/panel_layout.h"

namespace raylab {

// Before the panel's Begin: its default place and size on first use, or now (expanded) on a reset.
void placeNextPanel(Panel panel, bool reset);
// After the panel's End: moves or resizes its window where PanelLayout says; true when it did, so the
// panels must be drawn again to show the correction (this frame's draw data still has the old place).
bool keepPanelInside(Panel panel, PanelLayout& layout);
// After End of another window drawn this frame: its rectangle goes into layout.rects() as drawn.
void recordWindow(const char* title, PanelLayout& layout);

}  // namespace raylab
