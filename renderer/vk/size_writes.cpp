#include "renderer/vk/size_writes.h"

#include "renderer/vk/command_counts.h"

namespace raylab {

void updateSizes(VkCommandBuffer cmd, VkBuffer buffer, VkDeviceSize offset, VkDeviceSize bytes, const void* data) {
  vkCmdUpdateBuffer(cmd, buffer, offset, bytes, data);
  countCommand(cmd, CommandKind::SizeWrite);
}

void copySizes(VkCommandBuffer cmd, VkBuffer src, VkBuffer dst, const VkBufferCopy& region) {
  vkCmdCopyBuffer(cmd, src, dst, 1, &region);
  countCommand(cmd, CommandKind::SizeWrite);
}

}  // namespace raylab
