#pragma once
#include <string>
#include <vector>

namespace raylab {
// `raylab [options]`: the interactive lab window (app/window/). Without a display, or in a build without
// the window, it says so and renders headless as `raylab render` would.
int runWindowCommand(const std::vector<std::string>& args);
// Text of the window's own options (besides the render flags), for `raylab --help`.
std::string windowOptionsHelp();
}  // namespace raylab
