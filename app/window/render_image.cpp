#include "app/window/render_image.h"

#include "renderer/vk/vk_check.h"
#include "renderer/vk/vk_context.h"

namespace raylab {

RenderImage::RenderImage(const VulkanContext& ctx, uint32_t width, uint32_t height)
    : ctx_(ctx), width_(width), height_(height) {
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = VK_FORMAT_R8G8B8A8_UNORM;  // the buffer's byte order: R in the low byte
  info.extent = {width, height, 1};
  info.mipLevels = 1;
  info.arrayLayers = 1;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  VK_CHECK(vkCreateImage(ctx.device(), &info, nullptr, &image_));
  VkMemoryRequirements req;
  vkGetImageMemoryRequirements(ctx.device(), image_, &req);
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex = ctx.findMemoryType(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  VK_CHECK(vkAllocateMemory(ctx.device(), &alloc, nullptr, &memory_));
  VK_CHECK(vkBindImageMemory(ctx.device(), image_, memory_, 0));
}

RenderImage::~RenderImage() {
  vkDestroyImage(ctx_.device(), image_, nullptr);
  vkFreeMemory(ctx_.device(), memory_, nullptr);
}

}  // namespace raylab
