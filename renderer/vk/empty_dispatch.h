// The cost of one dispatch that does no work, as the wavefront issues its stages: a pipeline bound, push
// constants, one work group, then a compute barrier before the next (issue 36). Times the difference between
// runs of 2N and N such dispatches back to back with GPU timestamps, so the timestamps' own cost cancels;
// the median of a few submissions. With the counts of FrameStats::commands it estimates a frame's fixed
// cost: dispatches x this (the bench's fixed_cost_ms).
#pragma once

#include <cstdint>
#include <optional>

namespace raylab {

class VulkanContext;

// Microseconds per empty dispatch and its barrier; none where the device has no timestamps.
std::optional<double> measureEmptyDispatchUs(const VulkanContext& ctx, uint32_t dispatches = 256, uint32_t submissions = 5);

}  // namespace raylab
