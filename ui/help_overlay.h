// F1: the keys and mouse of the window, over everything.
#pragma once

namespace raylab {

void drawHelpOverlay(bool* open);

}  // namespace raylab
