#include "renderer/reorder/path_sorter.h"

#include <algorithm>


#include "renderer/reorder/key_accuracy.h"
#include "renderer/path_buffers.h"
#include "renderer/vk/stage_timer.h"
#include "renderer/vk/vk_context.h"

namespace raylab {
namespace {

// The first `bytes` of `from` to `to` at `offset`.
void copyInto(VkCommandBuffer cmd, const GpuBuffer& from, const GpuBuffer& to, VkDeviceSize bytes, VkDeviceSize offset) {
  VkBufferCopy region{0, offset, bytes};
  vkCmdCopyBuffer(cmd, from.handle(), to.handle(), 1, &region);
}

}  // namespace

struct PathSorter::Capture {
  GpuBuffer origin, direction, throughput, hitT, keys;
  bool haveRays = false, haveKeys = false;
  Capture(const VulkanContext& ctx, uint32_t n)
      : origin(ctx, VkDeviceSize(n) * 16, MemoryKind::HostVisible),
        direction(ctx, VkDeviceSize(n) * 16, MemoryKind::HostVisible),
        throughput(ctx, VkDeviceSize(n) * 16, MemoryKind::HostVisible),
        hitT(ctx, VkDeviceSize(n) * 4, MemoryKind::HostVisible),
        keys(ctx, VkDeviceSize(n) * 4, MemoryKind::HostVisible) {}
};

PathSorter::PathSorter(const VulkanContext& ctx, const Scene& scene, const Settings& settings,
                           glm::vec3 cameraPos, uint32_t maxPaths)
    : ctx_(ctx),
      keys_(ctx, scene, cameraPos, settings, maxPaths),
      maxPaths_(maxPaths),
      gather_(ctx, "gather_path_state", sizeof(gpu::PathStagePush), RL_PATH_GROUP_SIZE) {
  makeSorter(settings);
}

PathSorter::~PathSorter() = default;

void PathSorter::apply(const Settings& settings, glm::vec3 cameraPos, uint32_t maxPaths,
                       const SettingsChange& change) {
  if (change.reallocate) {
    maxPaths_ = maxPaths;
    sorter_.reset();
    captures_.clear();
  }
  keys_.apply(settings, cameraPos, maxPaths_, change);
  makeSorter(settings);
}

void PathSorter::makeSorter(const Settings& settings) {
  sortBits_ = settings.sortBits;
  if (!settings.sorts()) return;  // the sorter's scratch is only paid for while sorting
  if (!sorter_ || sorter_->algorithm() != settings.sort || sorter_->maxCount() < maxPaths_)
    sorter_ = std::make_unique<GpuSorter>(ctx_, settings.sort, maxPaths_);
}

// The readbacks of `bounce`, room for a whole frame's paths.
PathSorter::Capture& PathSorter::captureOf(uint32_t bounce, uint32_t framePaths) {
  if (captures_.size() <= bounce) captures_.resize(bounce + 1);
  if (!captures_[bounce] || captures_[bounce]->hitT.size() != VkDeviceSize(framePaths) * 4)
    captures_[bounce] = std::make_unique<Capture>(ctx_, framePaths);
  return *captures_[bounce];
}

void PathSorter::beginFrame() {
  for (auto& c : captures_)
    if (c) c->haveRays = c->haveKeys = false;
}

void PathSorter::recordAfterTrace(VkCommandBuffer cmd, const PathBuffers& buffers, uint32_t stateSet,
                                  uint32_t bounce, bool keyed, bool detailed, StageTimer* timer) {
  const uint32_t n = buffers.pathCount;
  if (bounce == 0 || !keyed) return;
  keys_.recordLearn(cmd, buffers.frameBlock.address(), stateSet, bounce, n, timer);
  if (!detailed) return;
  // The rays of this bounce with the predictions made for them, before shading overwrites them.
  Capture& c = captureOf(bounce, buffers.pathCount);
  const GpuBuffer* state = buffers.state[stateSet];
  copyInto(cmd, state[RL_STATE_ORIGIN], c.origin, VkDeviceSize(n) * 16, 0);
  copyInto(cmd, state[RL_STATE_DIRECTION], c.direction, VkDeviceSize(n) * 16, 0);
  copyInto(cmd, state[RL_STATE_THROUGHPUT], c.throughput, VkDeviceSize(n) * 16, 0);
  copyInto(cmd, buffers.hitT, c.hitT, VkDeviceSize(n) * 4, 0);
  c.haveRays = true;
  computeBarrier(cmd);
}

void PathSorter::recordKeys(VkCommandBuffer cmd, const PathBuffers& buffers, uint32_t stateSet,
                            uint32_t bounce, bool madeInShade, bool detailed, StageTimer* timer) {
  const uint32_t n = buffers.pathCount;
  // Over the live prefix only: past it, buffers.keys holds the dead keys the last sort moved there (every
  // slot is live until a frame's first sort, and the keys pass then covers them all).
  if (!madeInShade)
    keys_.recordKeys(cmd, buffers.frameBlock.address(), stateSet, bounce, buffers.keys.address(),
                     buffers.values.address(), n, timer, buffers.live.handle(), PathBuffers::kLiveDispatchOffset);
  if (detailed) {
    // Keys made now sort the rays of the next bounce.
    Capture& c = captureOf(bounce + 1, buffers.pathCount);
    copyInto(cmd, buffers.keys, c.keys, VkDeviceSize(n) * 4, 0);
    c.haveKeys = true;
    computeBarrier(cmd);
  }
}

void PathSorter::recordSort(VkCommandBuffer cmd, const PathBuffers& buffers, uint32_t n, StageTimer* timer) {
  {
    ScopedStage s(timer, cmd, "sort");  // the sorter fences its own passes
    // Live keys are < 2^(keyBits-1) and the dead key is all ones (KeyStage::keyBits), so keyBits - 1 bits
    // plus the sorter's own clamp bit (min(key, 2^bits), gpu_sort.h) order them: passing keyBits sorted one
    // bit more than needed, a whole fourth radix pass for 24-bit two-point keys.
    // Only the live prefix of the last sort (GpuFrame::live; every path before the first): the key stage
    // gave every slot past it the dead key, so the pairs there are already in place.
    // Settings::sortBits keeps only the top bits of what the sort compares (keyBits - 1 live bits and the
    // dead bit): the bits below are ignored, a radix pass less for each 8.
    const uint32_t bits = std::max(1u, keys_.keyBits() - 1), compared = bits + 1;
    const uint32_t ignored = sortBits_ > 0 && sortBits_ < compared ? compared - sortBits_ : 0;
    sorter_->record(cmd, buffers.keys.address(), buffers.values.address(), n, bits,
                    buffers.live.address() + RL_LIVE_COUNT * sizeof(uint32_t), ignored);
  }
}

uint32_t PathSorter::recordGather(VkCommandBuffer cmd, const PathBuffers& buffers, uint32_t n, uint32_t stateSet,
                                  StageTimer* timer) {
  // "reorder": every state array gathered into the other set, and the live prefix's new length.
  // The sort's pairs are GpuFrame::sortKeys and sortValues (buffers.keys, buffers.values), as the gathering
  // trace reads them; n is the frame block's path count.
  const gpu::PathStagePush gather{buffers.frameBlock.address(), 0, stateSet};
  recordStage(cmd, timer, "reorder", [&] { gather_.dispatchThreads(cmd, gather, n); });
  return 1u - stateSet;
}

void PathSorter::finishFrame(FrameStats& stats, bool detailed) {
  stats.keyBits = keys_.keyBits();
  stats.lengthCacheBytes = keys_.cacheMemoryBytes();
  stats.sortScratchBytes = sorter_ ? sorter_->scratchBytes() : 0;
  if (!detailed) return;
  stats.lengthCacheOccupancy = keys_.cacheOccupancy();
  for (size_t b = 1; b < captures_.size() && b < stats.bounces.size(); ++b) {
    // Only bounces whose rays were keyed this frame: elsewhere the predicted length is whatever the path
    // state held (auto's unsorted bounces showed 4e25 errors), so they keep the stats' "not measured".
    if (!captures_[b] || !captures_[b]->haveRays || !captures_[b]->haveKeys) continue;
    Capture& c = *captures_[b];
    size_t n = c.hitT.size() / 4;
    // Unpacked from the path-state layout (shared_types.h, RL_STATE_*): predicted length in throughput.w,
    // the path id (RL_DEAD_PATH once finished) in direction.w.
    const auto* direction = static_cast<const glm::vec4*>(c.direction.mapped());
    const auto* directionWords = static_cast<const uint32_t*>(c.direction.mapped());
    const auto* throughput = static_cast<const glm::vec4*>(c.throughput.mapped());
    std::vector<float> predicted(n);
    std::vector<uint32_t> alive(n);
    for (size_t i = 0; i < n; ++i) {
      predicted[i] = throughput[i].w;
      alive[i] = directionWords[4 * i + 3] != RL_DEAD_PATH ? 1u : 0u;
    }
    KeyAccuracyInput in{
        {static_cast<const glm::vec4*>(c.origin.mapped()), n},
        {direction, n},
        predicted,
        {static_cast<const float*>(c.hitT.mapped()), n},
        alive,
        c.haveKeys ? std::span<const uint32_t>(static_cast<const uint32_t*>(c.keys.mapped()), n)
                   : std::span<const uint32_t>()};
    KeyAccuracy a = measureKeyAccuracy(keys_.grid(), in, static_cast<uint32_t>(b), stats.keyBits,
                                       stats.lengthCacheBytes, stats.lengthCacheOccupancy);
    BounceStats& bs = stats.bounces[b];
    if (a.evaluated > 0) {
      bs.predictionErrorMean = a.meanError;
      bs.predictionErrorMedian = a.medianError;
      bs.cellHitRate = a.cellHitRate;
    }
    bs.distinctKeys = a.distinctKeys;
  }
  // Hundreds of MB of host-visible copies at 2048x1024: release them rather than hold them between
  // detailed frames (holding them was seen to slow the following frames on an H100).
  captures_.clear();
}

}  // namespace raylab
