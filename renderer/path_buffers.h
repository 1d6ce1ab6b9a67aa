// The GPU memory of one frame of the wavefront: two path-state sets (ping-pong for the reorder), the trace
// output, per-path results, the per-pixel accumulator and display image, counters, and sort keys/values.
#pragma once

#include <cstdint>

#include "renderer/vk/gpu_buffer.h"
#include "shaders/shared_types.h"

namespace raylab {

class VulkanContext;

struct PathBuffers {
  // Nothing here depends on the bounce count: the counters have room for RL_MAX_BOUNCES.
  PathBuffers(const VulkanContext& ctx, uint32_t width, uint32_t height, uint32_t sppPerFrame);

  uint32_t pathCount = 0;
  uint32_t pixelCount = 0;
  GpuBuffer state[2][RL_STATE_ARRAY_COUNT];  // indexed by RL_STATE_* (GpuPathState's arrays, in order)
  GpuBuffer hitT, hitTriangle, hitBarycentric, hitSteps;
  GpuBuffer results, accumulation, image;
  GpuBuffer counters;         // RL_COUNTER_* slots per bounce, cleared at the start of a frame
  GpuBuffer counterHistory;   // host-visible copy of `counters`, made once at the end of a frame
  GpuBuffer keys, values;     // sort input/output
  // RL_LIVE_* slots: the live-path count and indirect dispatch size, then one block per bounce that a
  // compacting shade appends to (RL_LIVE_APPEND)
  GpuBuffer live;
  GpuBuffer frameBlock;       // GpuFrame

  // Byte offset of the indirect dispatch arguments in `live` (trace and shade dispatch from there).
  static constexpr VkDeviceSize kLiveDispatchOffset = RL_LIVE_DISPATCH * sizeof(uint32_t);
  static constexpr VkDeviceSize kLiveBlockBytes = RL_LIVE_WORDS * sizeof(uint32_t);
  // Byte offset of the block the compacting shade of `bounce` appends to.
  static constexpr VkDeviceSize liveAppendOffset(uint32_t bounce) {
    return (RL_LIVE_APPEND + VkDeviceSize(bounce) * RL_LIVE_WORDS) * sizeof(uint32_t);
  }
  // Bytes of counters for `bounces` bounces.
  static constexpr VkDeviceSize counterBytes(uint32_t bounces) {
    return VkDeviceSize(bounces) * RL_COUNTER_STRIDE * sizeof(uint32_t);
  }

  // The GpuFrame block with every address filled in; the caller sets camera, scene and frame parameters.
  gpu::GpuFrame addresses() const;
  uint64_t pathStateBytes() const;
};

}  // namespace raylab
