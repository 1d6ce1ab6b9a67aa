// The GPU memory of one frame of the wavefront: two path-state sets (ping-pong for the reorder), the trace
// output, per-path results, the per-pixel accumulator and display image, counters, and sort keys/values.
#pragma once

#include <cstdint>

#include "renderer/gpu_buffer.h"
#include "shaders/shared_types.h"

namespace raylab {

class VulkanContext;

// Slots of the counters buffer (see shaders/shared_types.h, GpuFrame::counters).
enum CounterSlot : uint32_t { kCounterRays = 0, kCounterSimtActive = 1, kCounterSimtSlots = 2, kCounterCount = 4 };

struct PathBuffers {
  PathBuffers(const VulkanContext& ctx, uint32_t width, uint32_t height, uint32_t sppPerFrame, uint32_t bounces);

  uint32_t pathCount = 0;
  uint32_t pixelCount = 0;
  GpuBuffer state[2][7];  // origin, direction, throughput, radiance, pathId, alive, predictedLength
  GpuBuffer hitT, hitTriangle, hitBarycentric, hitSteps;
  GpuBuffer results, accumulation, image;
  GpuBuffer counters;         // live counters, cleared after every trace
  GpuBuffer counterHistory;   // kCounterCount per bounce, copied after every trace (host visible)
  GpuBuffer keys, values;     // sort input/output
  GpuBuffer live;             // live-path count and indirect dispatch size (GpuFrame::live)
  GpuBuffer frameBlock;       // GpuFrame

  // The GpuFrame block with every address filled in; the caller sets camera, scene and frame parameters.
  gpu::GpuFrame addresses() const;
  uint64_t pathStateBytes() const;
};

}  // namespace raylab
