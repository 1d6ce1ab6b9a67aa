// The transfers that write indirect dispatch sizes (GpuFrame::live) from the host side of the frame: each is
// recorded here and counted as a size write (command_counts.h), as a shader that writes them is counted by
// its pipeline (WritesSizes::Yes).
#pragma once

#include <cstdint>

#include <vulkan/vulkan.h>

namespace raylab {

// vkCmdUpdateBuffer of `bytes` (a multiple of 4, at most 65536) of sizes at `offset` of `buffer`.
void updateSizes(VkCommandBuffer cmd, VkBuffer buffer, VkDeviceSize offset, VkDeviceSize bytes, const void* data);
// vkCmdCopyBuffer of one region of sizes within or between buffers.
void copySizes(VkCommandBuffer cmd, VkBuffer src, VkBuffer dst, const VkBufferCopy& region);

}  // namespace raylab
