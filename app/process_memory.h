// How much memory this process holds, from /proc/self/status (Linux): what the window's soak reports after
// warm-up and at the end, to show that thousands of frames do not make it grow.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace raylab {

struct ProcessMemory {
  uint64_t residentKiB = 0;      // VmRSS: resident now
  uint64_t peakResidentKiB = 0;  // VmHWM: the most it was resident so far
};

// The VmRSS and VmHWM lines of a /proc/PID/status text; nothing when VmRSS is missing or malformed.
std::optional<ProcessMemory> parseProcStatus(const std::string& statusText);
// This process's figures; nothing where /proc/self/status cannot be read (not Linux).
std::optional<ProcessMemory> readProcessMemory();

// One JSON object on one line, e.g. {"memory":"warm","frame":500,"vm_rss_kib":81234,"vm_hwm_kib":90000};
// "vm_rss_kib" is null where the figures could not be read.
std::string memoryReportLine(const std::string& label, uint64_t frame, const std::optional<ProcessMemory>& memory);

}  // namespace raylab
