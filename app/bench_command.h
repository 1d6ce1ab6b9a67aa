#pragma once
#include <string>
#include <vector>

namespace raylab {
// `raylab bench ...`: sweeps cases x strategies x sorts x parameters; writes results.csv, results.jsonl.
int runBenchCommand(const std::vector<std::string>& args);
}  // namespace raylab
