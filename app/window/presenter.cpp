#include "app/window/presenter.h"

#include <chrono>

#include "app/window/imgui_layer.h"
#include "app/window/render_image.h"
#include "app/window/swapchain.h"
#include "app/window/wall_clock.h"
#include "renderer/vk/vk_check.h"
#include "renderer/vk/vk_context.h"

namespace raylab {
namespace {

void imageBarrier(VkCommandBuffer cmd, VkImage image, VkImageLayout from, VkImageLayout to, VkPipelineStageFlags srcStage,
                  VkAccessFlags srcAccess, VkPipelineStageFlags dstStage, VkAccessFlags dstAccess) {
  VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  b.srcAccessMask = srcAccess;
  b.dstAccessMask = dstAccess;
  b.oldLayout = from;
  b.newLayout = to;
  b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.image = image;
  b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  vkCmdPipelineBarrier(cmd, srcStage, dstStage, 0, 0, nullptr, 0, nullptr, 1, &b);
}

VkSemaphore makeSemaphore(VkDevice device) {
  VkSemaphoreCreateInfo info{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
  VkSemaphore s;
  VK_CHECK(vkCreateSemaphore(device, &info, nullptr, &s));
  return s;
}

}  // namespace

Presenter::Presenter(const VulkanContext& ctx, Swapchain& swapchain, ImGuiLayer& layer)
    : ctx_(ctx), swapchain_(swapchain), layer_(layer) {
  VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  poolInfo.queueFamilyIndex = ctx.queueFamily();
  VK_CHECK(vkCreateCommandPool(ctx.device(), &poolInfo, nullptr, &pool_));
  VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  alloc.commandPool = pool_;
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  VK_CHECK(vkAllocateCommandBuffers(ctx.device(), &alloc, &cmd_));
  VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  VK_CHECK(vkCreateFence(ctx.device(), &fenceInfo, nullptr, &fence_));
  acquired_ = makeSemaphore(ctx.device());
  onSwapchainRecreated();
}

Presenter::~Presenter() {
  vkDeviceWaitIdle(ctx_.device());
  for (VkSemaphore s : rendered_) vkDestroySemaphore(ctx_.device(), s, nullptr);
  vkDestroySemaphore(ctx_.device(), acquired_, nullptr);
  vkDestroyFence(ctx_.device(), fence_, nullptr);
  vkDestroyCommandPool(ctx_.device(), pool_, nullptr);
}

void Presenter::onSwapchainRecreated() {
  for (VkSemaphore s : rendered_) vkDestroySemaphore(ctx_.device(), s, nullptr);
  rendered_.clear();
  for (uint32_t i = 0; i < swapchain_.imageCount(); ++i) rendered_.push_back(makeSemaphore(ctx_.device()));
}

PresentedFrame Presenter::drawFrame(const ShownImage& shown, ImDrawData* ui, bool captureWindow, bool nearest) {
  PresentedFrame out;
  uint32_t index = 0;
  VkResult acquired = swapchain_.acquire(acquired_, &index);
  if (acquired == VK_ERROR_OUT_OF_DATE_KHR) {
    out.recreateSwapchain = true;
    return out;
  }
  captureWindow = captureWindow && swapchain_.readable();
  if (!image_ || image_->width() != shown.width || image_->height() != shown.height) {
    image_ = std::make_unique<RenderImage>(ctx_, shown.width, shown.height);
    imageVersion_ = 0;
  }
  const VkExtent2D extent = swapchain_.extent();
  if (captureWindow && capture_.size() < VkDeviceSize(extent.width) * extent.height * 4)
    capture_ = GpuBuffer(ctx_, VkDeviceSize(extent.width) * extent.height * 4, MemoryKind::HostVisible);

  auto start = std::chrono::steady_clock::now();
  VK_CHECK(vkResetCommandBuffer(cmd_, 0));
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  VK_CHECK(vkBeginCommandBuffer(cmd_, &begin));
  record(cmd_, shown, ui, index, captureWindow, nearest);
  VK_CHECK(vkEndCommandBuffer(cmd_));

  VkPipelineStageFlags waitStage = VK_PIPELINE_STAGE_TRANSFER_BIT;  // the first use of the image is the blit
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.waitSemaphoreCount = 1;
  submit.pWaitSemaphores = &acquired_;
  submit.pWaitDstStageMask = &waitStage;
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd_;
  submit.signalSemaphoreCount = 1;
  submit.pSignalSemaphores = &rendered_[index];
  VK_CHECK(vkResetFences(ctx_.device(), 1, &fence_));
  VK_CHECK(vkQueueSubmit(ctx_.queue(), 1, &submit, fence_));
  VK_CHECK(vkWaitForFences(ctx_.device(), 1, &fence_, VK_TRUE, UINT64_MAX));
  out.wallMs = msSince(start);
  out.rendered = true;
  if (captureWindow) {
    out.window = readCapture();
    out.windowWidth = extent.width, out.windowHeight = extent.height;
  }
  VkResult presented = swapchain_.present(rendered_[index], index);
  out.recreateSwapchain = acquired == VK_SUBOPTIMAL_KHR || presented != VK_SUCCESS;
  return out;
}

void Presenter::record(VkCommandBuffer cmd, const ShownImage& shown, ImDrawData* ui, uint32_t index, bool capture,
                       bool nearest) {
  // The render image changes only when a render frame completes or a preview is made; most UI frames of a
  // render in steps only blit it again.
  if (shown.version != imageVersion_) recordCopy(cmd, shown);
  imageVersion_ = shown.version;
  recordBlit(cmd, index, nearest);
  const VkImage target = swapchain_.image(index);
  imageBarrier(cmd, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
               VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
               VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
  layer_.record(cmd, index, ui);
  if (capture) recordCapture(cmd, index);
  const VkImageLayout now = capture ? VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL : VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  imageBarrier(cmd, target, now, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR,
               capture ? VK_PIPELINE_STAGE_TRANSFER_BIT : VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
               capture ? 0 : VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0);
}

// Render buffer -> render image, left in TRANSFER_SRC layout for the blits of this and later UI frames.
void Presenter::recordCopy(VkCommandBuffer cmd, const ShownImage& shown) {
  VkBufferMemoryBarrier written{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER};
  written.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  written.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
  written.srcQueueFamilyIndex = written.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  written.buffer = shown.pixels->handle();
  written.size = VK_WHOLE_SIZE;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 1,
                       &written, 0, nullptr);
  const VkImage render = image_->handle();
  imageBarrier(cmd, render, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
               0, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
  VkBufferImageCopy copy{};
  copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  copy.imageExtent = {shown.width, shown.height, 1};
  vkCmdCopyBufferToImage(cmd, shown.pixels->handle(), render, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
  imageBarrier(cmd, render, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
               VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
               VK_ACCESS_TRANSFER_READ_BIT);
}

// Render image -> swapchain image (scaled to the window), leaving the swapchain image in TRANSFER_DST layout.
void Presenter::recordBlit(VkCommandBuffer cmd, uint32_t index, bool nearest) {
  const VkImage render = image_->handle(), target = swapchain_.image(index);
  imageBarrier(cmd, target, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
               0, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
  const VkExtent2D extent = swapchain_.extent();
  VkImageBlit blit{};
  blit.srcSubresource = blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  blit.srcOffsets[1] = {int32_t(image_->width()), int32_t(image_->height()), 1};
  blit.dstOffsets[1] = {int32_t(extent.width), int32_t(extent.height), 1};
  vkCmdBlitImage(cmd, render, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit,
                 nearest ? VK_FILTER_NEAREST : VK_FILTER_LINEAR);
}

// Reads the finished window (render and panels) into the host-visible capture buffer, leaving the image in
// TRANSFER_SRC layout.
void Presenter::recordCapture(VkCommandBuffer cmd, uint32_t index) {
  const VkImage target = swapchain_.image(index);
  imageBarrier(cmd, target, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
               VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
               VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
  const VkExtent2D extent = swapchain_.extent();
  VkBufferImageCopy copy{};
  copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  copy.imageExtent = {extent.width, extent.height, 1};
  vkCmdCopyImageToBuffer(cmd, target, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, capture_.handle(), 1, &copy);
  VkBufferMemoryBarrier toHost{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER};
  toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  toHost.srcQueueFamilyIndex = toHost.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  toHost.buffer = capture_.handle();
  toHost.size = VK_WHOLE_SIZE;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 0, nullptr, 1, &toHost, 0, nullptr);
}

std::vector<uint32_t> Presenter::readCapture() const {
  const VkExtent2D extent = swapchain_.extent();
  const auto* pixels = static_cast<const uint32_t*>(capture_.mapped());
  std::vector<uint32_t> rgba(pixels, pixels + size_t(extent.width) * extent.height);
  for (uint32_t& p : rgba) {
    if (swapchain_.bgr()) p = (p & 0xff00ff00u) | ((p & 0xffu) << 16) | ((p >> 16) & 0xffu);
    p |= 0xff000000u;  // the window is opaque whatever alpha the panels left behind
  }
  return rgba;
}

}  // namespace raylab
