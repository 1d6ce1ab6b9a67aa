// The one place a thread count becomes the size of a compute dispatch: rows of at most the device's
// maxComputeWorkGroupCount[0] groups, as many rows as needed (shaders/dispatch_grid.h has the layout,
// shaders/dispatch_index.glsl the shaders' side). So every path count the settings allow runs on every
// device, lavapipe's 65535 groups in x included.
#pragma once

#include <cstdint>

namespace raylab {

struct DispatchSize {
  uint32_t x = 0;  // groups in a row; 0: nothing to dispatch
  uint32_t y = 1;  // rows
};

// Groups of `groupSize` threads covering `threads`, in rows of `rowGroups` (DeviceInfo::dispatchRowGroups);
// throws VulkanError where even `maxRows` rows (maxComputeWorkGroupCount[1]) are too few.
DispatchSize dispatchSizeFor(uint64_t threads, uint32_t groupSize, uint32_t rowGroups, uint32_t maxRows);

}  // namespace raylab
