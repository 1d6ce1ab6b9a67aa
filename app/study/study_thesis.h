// `raylab study temple --thesis`: the source study's own table re-measured (../shared/seed, Tables 4.1 and
// 4.2 and section 4.3): its three temple views at 2048x1024 with 4 bounces, for the unsorted tracer,
// fixed-length keys, Meister et al.'s origin+direction key, average cached lengths and Gaussian lengths reset
// at variance 20 on a camera-clamped grid, each with the thesis's bitonic sort and our radix sort. Two
// `raylab bench` sweeps (the Gaussian's clamp would otherwise double every cell) and app/study/thesis_table.py,
// which lays the figures out in the thesis's table shape beside its published ones.
#pragma once

#include <string>
#include <vector>

#include "app/study/study_plan.h"

namespace raylab {

struct ThesisSweep {
  std::string folder;                  // OUT/thesis-keys, OUT/thesis-gaussian
  std::string size;                    // WxH: 2048x1024, the CPU's or --sizes's
  std::vector<std::string> benchArgs;  // its `raylab bench` arguments
};

// The two sweeps; a CPU device gets 256x128 and fewer frames (lavapipe takes seconds a 2048x1024 frame).
// Throws UsageError for a target other than the temple, or options --thesis does not take.
std::vector<ThesisSweep> thesisPlan(const StudyOptions& options, bool cpuDevice);

// Runs the sweeps and writes OUT/thesis.md and OUT/thesis.html; the exit status.
int runThesisStudy(const StudyOptions& options, bool cpuDevice);

}  // namespace raylab
