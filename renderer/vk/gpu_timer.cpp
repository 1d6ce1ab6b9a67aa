#include "renderer/vk/gpu_timer.h"

#include <algorithm>

#include "renderer/vk/vk_check.h"
#include "renderer/vk/vk_context.h"

namespace raylab {

// Four queries per scope: begin, end, and after each a second timestamp that is never read. lavapipe
// writes a timestamp only at the next flush once a framebuffer is bound (any frame of the window's UI pass
// leaves one bound), and each timestamp flushes the one before: without the second writes, a scope's begin
// was taken after its work and its end right after that, so in the window every stage read ~0.05 ms while
// the frame's span was hundreds. Headless had no framebuffer and was right. On GPUs the extra writes
// cost nothing.
// Flushing was not enough: the flush hands the deferred timestamp to llvmpipe's rasterizer threads and
// returns, so on a CPU device a timestamp could still be taken after the next dispatch had begun (it
// competes with that dispatch's threads for the cores). The window's stages then covered 66-88% of its
// frame against headless's 98%, and single stages read 0.47-1.95x headless (trace 9.1 ms against 19.4 at
// 320x180, 2 cores). On CPU devices each timestamp that is read is therefore also copied out with
// VK_QUERY_RESULT_WAIT_BIT (settle below), which waits until it is written: coverage became 97-98% on both
// sides and every stage within 0.91-1.01x of headless in a quiet run (docs/lab-window.md), with no
// measurable cost headless (none at 320x180: 49-51 ms a frame with it, 48-54 without).
GpuTimer::GpuTimer(const VulkanContext& ctx, uint32_t maxScopes) : ctx_(ctx), capacity_(4 * maxScopes) {
  if (!ctx.info().timestamps) return;  // stage times then stay empty; frame wall time still works
  VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  info.queryType = VK_QUERY_TYPE_TIMESTAMP;
  info.queryCount = capacity_;
  VK_CHECK(vkCreateQueryPool(ctx.device(), &info, nullptr, &pool_));
  if (ctx.info().isCpu) settle_ = GpuBuffer(ctx, 8ull * capacity_);
}

GpuTimer::~GpuTimer() {
  if (pool_) vkDestroyQueryPool(ctx_.device(), pool_, nullptr);
}

void GpuTimer::reset(VkCommandBuffer cmd) {
  used_ = 0;
  scopes_.clear();
  open_.clear();
  bounce_ = -1;
  if (pool_) vkCmdResetQueryPool(cmd, pool_, 0, capacity_);
}

void GpuTimer::begin(VkCommandBuffer cmd, std::string_view stage) {
  if (!pool_ || used_ + 4 > capacity_) {
    open_.push_back(UINT32_MAX);
    return;
  }
  scopes_.push_back({std::string(stage), bounce_, used_});
  open_.push_back(static_cast<uint32_t>(scopes_.size() - 1));
  // BOTTOM_OF_PIPE: written once all earlier commands completed. A TOP_OF_PIPE start would be taken
  // while the previous stage still runs and charge part of it to this one.
  vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, pool_, used_);
  vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, pool_, used_ + 1);
  settle(cmd, used_);
  used_ += 4;
}

void GpuTimer::end(VkCommandBuffer cmd) {
  if (open_.empty()) return;
  uint32_t scope = open_.back();
  open_.pop_back();
  if (scope == UINT32_MAX) return;
  vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, pool_, scopes_[scope].first + 2);
  vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, pool_, scopes_[scope].first + 3);
  settle(cmd, scopes_[scope].first + 2);
}

// CPU devices only (settle_ is empty elsewhere): each query lands in its own 8 bytes, so the copies never
// write the same memory and need no barrier between them.
void GpuTimer::settle(VkCommandBuffer cmd, uint32_t query) {
  if (!settle_.valid()) return;
  vkCmdCopyQueryPoolResults(cmd, pool_, query, 1, settle_.handle(), 8ull * query, 8,
                            VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT);
}

std::vector<StageTime> GpuTimer::collect() {
  std::vector<StageTime> out;
  if (!pool_ || used_ == 0) return out;
  std::vector<uint64_t> ticks(used_);
  VK_CHECK(vkGetQueryPoolResults(ctx_.device(), pool_, 0, used_, ticks.size() * sizeof(uint64_t), ticks.data(),
                                 sizeof(uint64_t), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
  double nsPerTick = ctx_.info().timestampPeriodNs;
  uint64_t first = UINT64_MAX, last = 0;
  for (const Scope& s : scopes_) {
    uint64_t a = ticks[s.first], b = ticks[s.first + 2];
    out.push_back({s.stage, s.bounce, b > a ? (b - a) * nsPerTick * 1e-6 : 0.0});
    first = std::min(first, a);
    last = std::max(last, b);
  }
  spanMs_ = last > first ? (last - first) * nsPerTick * 1e-6 : 0.0;
  return out;
}

}  // namespace raylab
