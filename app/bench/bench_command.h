#pragma once
#include <string>
#include <vector>

namespace raylab {
// `raylab bench ...`: sweeps cases x strategies x sorts x parameters, every cell in --rounds interleaved
// rounds; writes results.jsonl (a record per cell and round), results.csv, cells.jsonl and resolution.txt.
int runBenchCommand(const std::vector<std::string>& args);
}  // namespace raylab
