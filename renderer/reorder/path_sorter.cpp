#include "renderer/reorder/path_sorter.h"

#include <algorithm>

#include "renderer/path_buffers.h"
#include "renderer/reorder/key_functions.h"
#include "renderer/vk/stage_timer.h"
#include "renderer/vk/vk_context.h"

namespace raylab {

PathSorter::PathSorter(const VulkanContext& ctx, const Scene& scene, const Settings& settings,
                           glm::vec3 cameraPos, uint32_t maxPaths)
    : ctx_(ctx),
      keys_(ctx, scene, cameraPos, settings, maxPaths),
      maxPaths_(maxPaths),
      gather_(ctx, "gather_path_state", sizeof(gpu::PathStagePush), RL_PATH_GROUP_SIZE, {}, WritesSizes::Yes) {
  makeSorter(settings);
}

PathSorter::~PathSorter() = default;

void PathSorter::apply(const Settings& settings, glm::vec3 cameraPos, uint32_t maxPaths,
                       const SettingsChange& change) {
  if (change.reallocate) {
    maxPaths_ = maxPaths;
    sorter_.reset();
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

void PathSorter::recordLearn(VkCommandBuffer cmd, const PathBuffers& buffers, uint32_t stateSet, uint32_t bounce,
                             StageTimer* timer) {
  keys_.recordLearn(cmd, buffers.frameBlock.address(), stateSet, bounce, buffers.pathCount, timer);
}

void PathSorter::recordKeys(VkCommandBuffer cmd, const PathBuffers& buffers, uint32_t stateSet,
                            uint32_t bounce, bool madeInShade, StageTimer* timer) {
  const uint32_t n = buffers.pathCount;
  // Over the live prefix only: past it, buffers.keys holds the dead keys the last sort moved there (every
  // slot is live until a frame's first sort, and the keys pass then covers them all).
  if (!madeInShade)
    keys_.recordKeys(cmd, buffers.frameBlock.address(), stateSet, bounce, buffers.keys.address(),
                     buffers.values.address(), n, timer, buffers.live.handle(), PathBuffers::kLiveDispatchOffset);
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
    const uint32_t bits = std::max(1u, keys_.keyBits() - 1);
    sorter_->record(cmd, buffers.keys.address(), buffers.values.address(), n, bits,
                    buffers.live.address() + RL_LIVE_COUNT * sizeof(uint32_t), ignoredKeyBits(bits, sortBits_));
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

void PathSorter::finishFrame(FrameStats& stats) const {
  stats.keyBits = keys_.keyBits();
  stats.lengthCacheBytes = keys_.cacheMemoryBytes();
  stats.sortScratchBytes = sorter_ ? sorter_->scratchBytes() : 0;
}

}  // namespace raylab
