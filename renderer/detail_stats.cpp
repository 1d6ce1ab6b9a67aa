#include "renderer/detail_stats.h"

#include <algorithm>
#include <stdexcept>

#include "renderer/detail_sums.h"
#include "renderer/vk/stage_timer.h"

namespace raylab {
namespace {

constexpr VkDeviceSize kSumsBytes = sizeof(gpu::GpuDetailSums);

LazyPipeline detailPass(const VulkanContext& ctx, const char* shader) {
  return LazyPipeline(ctx, shader, sizeof(gpu::DetailPush), RL_DETAIL_GROUP_SIZE);
}

// Groups for `count` items: each loops over its share, at most RL_DETAIL_MAX_GROUPS of them.
uint32_t groupsFor(uint32_t count) {
  return std::clamp((count + RL_DETAIL_GROUP_SIZE - 1) / RL_DETAIL_GROUP_SIZE, 1u, RL_DETAIL_MAX_GROUPS);
}

// Bytes of the distinct-key bitmap for keys of `liveBits` bits (at least one word).
VkDeviceSize bitmapBytes(uint32_t liveBits) {
  return std::max<VkDeviceSize>(4, (VkDeviceSize(1) << std::min(liveBits, uint32_t(RL_DETAIL_KEY_BITMAP_BITS))) / 8);
}

}  // namespace

DetailStats::DetailStats(const VulkanContext& ctx)
    : ctx_(ctx),
      warps_(detailPass(ctx, "detail_warps")),
      prediction_(detailPass(ctx, "detail_prediction")),
      keys_(detailPass(ctx, "detail_keys")),
      cache_(detailPass(ctx, "detail_cache")) {}

void DetailStats::recordClear(VkCommandBuffer cmd, uint32_t bounces) {
  bounces = std::max(bounces, 1u);
  if (!sums_.valid() || sums_.size() < kSumsBytes * bounces) {
    sums_ = GpuBuffer(ctx_, kSumsBytes * bounces);
    hostSums_ = GpuBuffer(ctx_, kSumsBytes * bounces, MemoryKind::HostVisible);
  }
  ran_.assign(bounces, Ran{});
  cacheRan_ = false;
  retired_.clear();  // the last frame, which may have used them, has completed
  sums_.recordFill(cmd, 0);
  computeBarrier(cmd);
}

gpu::DetailPush DetailStats::pushFor(uint32_t bounce) const {
  if (bounce >= ran_.size()) throw std::logic_error("DetailStats: bounce " + std::to_string(bounce) + " not cleared");
  gpu::DetailPush push{};
  push.sums = sums_.address() + kSumsBytes * bounce;
  return push;
}

void DetailStats::recordWarps(VkCommandBuffer cmd, VkDeviceAddress steps, uint32_t count, uint32_t bounce,
                              StageTimer* timer) {
  gpu::DetailPush push = pushFor(bounce);
  push.values = steps;
  push.count = count;
  recordStage(cmd, timer, "counters", [&] { warps_.get().dispatchGroups(cmd, push, groupsFor(count)); });
  ran_[bounce].warps = true;
}

void DetailStats::recordPrediction(VkCommandBuffer cmd, VkDeviceAddress frameBlock, VkDeviceAddress keyParams,
                                   uint32_t stateSet, uint32_t count, float invDiagonal, uint32_t bounce,
                                   StageTimer* timer) {
  gpu::DetailPush push = pushFor(bounce);
  push.frame = frameBlock;
  push.keyParams = keyParams;
  push.stateSet = stateSet;
  push.count = count;
  push.invDiagonal = invDiagonal;
  recordStage(cmd, timer, "counters", [&] { prediction_.get().dispatchGroups(cmd, push, groupsFor(count)); });
  ran_[bounce].prediction = true;
}

void DetailStats::ensureBitmap(uint32_t liveBits) {
  if (bitmap_.valid() && bitmap_.size() >= bitmapBytes(liveBits)) return;
  // A smaller bitmap may be in this frame's commands already: kept until the next frame starts.
  if (bitmap_.valid()) retired_.push_back(std::move(bitmap_));
  bitmap_ = GpuBuffer(ctx_, bitmapBytes(liveBits));
}

void DetailStats::recordDistinctKeys(VkCommandBuffer cmd, VkDeviceAddress keys, uint32_t count, uint32_t liveBits,
                                     uint32_t bounce, StageTimer* timer) {
  gpu::DetailPush push = pushFor(bounce);
  ensureBitmap(liveBits);
  push.values = keys;
  push.bitmap = bitmap_.address();
  push.count = count;
  push.keyShift = distinctKeyShift(liveBits);
  recordStage(cmd, timer, "counters", [&] {
    vkCmdFillBuffer(cmd, bitmap_.handle(), 0, bitmapBytes(liveBits), 0);
    computeBarrier(cmd);
    keys_.get().dispatchGroups(cmd, push, groupsFor(count));
  });
  ran_[bounce].keys = true;
}

void DetailStats::recordCacheUsed(VkCommandBuffer cmd, VkDeviceAddress keyParams, uint32_t entryCount,
                                  StageTimer* timer) {
  gpu::DetailPush push = pushFor(0);
  push.keyParams = keyParams;
  push.count = entryCount;
  recordStage(cmd, timer, "counters", [&] { cache_.get().dispatchGroups(cmd, push, groupsFor(entryCount)); });
  cacheRan_ = true;
}

void DetailStats::recordToHost(VkCommandBuffer cmd) const {
  if (ran_.empty()) return;
  const VkBufferCopy copy{0, 0, kSumsBytes * ran_.size()};
  vkCmdCopyBuffer(cmd, sums_.handle(), hostSums_.handle(), 1, &copy);
}

const gpu::GpuDetailSums& DetailStats::sums(uint32_t bounce) const {
  if (bounce >= ran_.size()) throw std::logic_error("DetailStats: no sums for bounce " + std::to_string(bounce));
  return static_cast<const gpu::GpuDetailSums*>(hostSums_.mapped())[bounce];
}

}  // namespace raylab
