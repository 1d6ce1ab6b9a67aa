// Runs another program (the Python report and chart scripts) and waits for it: no shell, so paths with
// spaces or quotes reach it as they are.
#pragma once

#include <string>
#include <vector>

namespace raylab {

// The exit status of argv[0] (found through PATH unless it names a path), 127 when it cannot be started, or
// 128 + the signal that ended it.
int runChildProcess(const std::vector<std::string>& argv);

}  // namespace raylab
