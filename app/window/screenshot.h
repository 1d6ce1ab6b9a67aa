// Screenshots: a PNG and its JSON sidecar (app/sidecar.h) in the screenshot folder.
#pragma once

#include <string>
#include <vector>

#include "app/sidecar.h"

namespace raylab {

// Writes DIR/NAME.png and DIR/NAME.json (both through writeFileChecked, and neither when one fails),
// creating DIR; returns the PNG's path. Throws std::runtime_error (WriteError when a write failed).
std::string writeScreenshot(const std::string& dir, const std::string& name, const std::vector<uint32_t>& rgba,
                            SidecarContent content);

// "render-20261123-193301" (or "-2", "-3" when that name is taken in DIR): for F12 and Shift+F12, and
// recorded camera paths ("path-...").
std::string freshScreenshotName(const std::string& dir, const std::string& kind);

}  // namespace raylab
