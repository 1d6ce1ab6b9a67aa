#pragma once
#include <string>
#include <vector>

namespace raylab {
// `raylab render ...`: renders frames headless, writes the PNG and optionally the stats JSON.
int runRenderCommand(const std::vector<std::string>& args);
}  // namespace raylab
