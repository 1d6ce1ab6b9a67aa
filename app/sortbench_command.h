// `raylab sortbench`: times the GPU sorts alone (Vulkan timestamps around GpuSorter::record), checks their
// output once per (sort, n) against std::stable_sort and prints a table (optionally a CSV file).
#pragma once

#include <string>
#include <vector>

namespace raylab {

// `args`: the flags after "sortbench" (see the usage text: `raylab sortbench --help`).
// Returns 0 on success, 1 on a wrong sort result or a device failure, 2 on bad flags.
int runSortBenchCommand(const std::vector<std::string>& args);

}  // namespace raylab
