// `raylab tracebench`: times the BVH traversal alone on each kind of ray a path tracer traces (camera rays,
// one diffuse bounce from their hits, next-event estimation's shadow rays from the same hits), the way the
// public GPU traversal kernels are measured: one dispatch of hit_query.comp per kind, Vulkan timestamps
// around it, interleaved rounds back to back in one submission after warm-up rounds. Checks a sample of
// every kind against Embree and prints a table of rays per second (optionally a CSV file).
#pragma once

#include <string>
#include <vector>

namespace raylab {

// `args`: the flags after "tracebench" (`raylab tracebench --help`). Returns 0 on success, 1 when the GPU's
// answers disagree with Embree's or the device fails, 2 on bad flags, 3 on an unusable scene.
int runTraceBenchCommand(const std::vector<std::string>& args);

}  // namespace raylab
