#pragma once
#include <string>
#include <vector>

namespace raylab {
// `raylab study SCENE[@VIEW] ...`: the standard sweep of where sorting pays on one scene, and its HTML report.
int runStudyCommand(const std::vector<std::string>& args);
}  // namespace raylab
