// The frame loop as a list of steps (PathTracer::buildSteps): every stage of a frame is one FrameStep over the
// whole frame, in the order a whole frame records them. The host-side decisions (which bounces sort, which
// state set each stage reads, which dispatches are fused) are made here, once per frame, and each step's
// closure keeps the ones it needs, so recording the steps over several submissions records exactly the
// commands of one.
#include "renderer/path_tracer.h"

#include "renderer/detail_stats.h"
#include "renderer/detail_sums.h"
#include "renderer/heatmap/heatmap_pass.h"
#include "renderer/heatmap/heatmap_rules.h"
#include "renderer/reorder/key_functions.h"
#include "renderer/reorder/key_strategies.h"
#include "renderer/reorder/path_sorter.h"
#include "renderer/rt_tracer.h"
#include "renderer/vk/size_writes.h"
#include "renderer/vk/stage_timer.h"

namespace raylab {

void PathTracer::addStep(const char* name, int bounce, std::function<void(VkCommandBuffer)> record) {
  steps_.push_back({name, bounce, std::move(record)});
}

// The frame's sort plan, the heatmap's view for it, then setup, the kernel's steps and the end of the frame.
void PathTracer::buildSteps() {
  steps_.clear();
  nextStep_ = 0;
  const bool sorting = settings_.sorts();
  framePlan_ = sorting ? sortPolicy_.plan(settings_.sortPolicy, settings_.bounces) : SortPlan{};
  heatmap_->configure(settings_, sorting ? pathSorter_->keys().paramsAddress() : 0,
                      sorting ? &pathSorter_->keys().grid().gpu : nullptr, sorting && pathSorter_->keys().hasCache());
  addStep("setup", -1, [this](VkCommandBuffer cmd) {
    recordStage(cmd, &timer_, "setup", [&] {
      recordFrameBlock(cmd);
      buffers_->counters.recordFill(cmd, 0);
      computeBarrier(cmd);
      heatmap_->recordClear(cmd);
    });
    // A frame's details start from zero sums: none of an earlier (possibly abandoned) frame counts for it.
    if (detailedStats_)
      recordStage(cmd, &timer_, "counters", [&] { details_->recordClear(cmd, countedBounces()); });
  });
  const gpu::PathStagePush push{buffers_->frameBlock.address(), 0, 0};
  if (settings_.kernel == Kernel::Megakernel)
    buildMegakernelSteps(push);
  else
    buildWavefrontSteps(push);
  buildEndSteps(push);
}

void PathTracer::buildMegakernelSteps(const gpu::PathStagePush& push) {
  addStep("megakernel", -1, [this, push](VkCommandBuffer cmd) {
    const uint32_t n = buffers_->pathCount;
    const ComputePipeline& megakernel = megakernel_[settings_.countSimt][countsSteps(-1)][traversalOf(settings_.bvh)].get();
    recordStage(cmd, &timer_, "megakernel", [&] {
      if (!usesRt()) {
        megakernel.dispatchThreads(cmd, push, n);
      } else if (settings_.ser == Ser::Off) {
        rt_->megakernel(cmd, push, n);
      } else {
        // The hint: the top bits (at most 16) of the key Settings::strategy gives each ray.
        const KeyStrategy hint = settings_.ser == Ser::Hint ? settings_.strategy : KeyStrategy::None;
        const uint32_t bits = hint == KeyStrategy::None ? 0 : spatialKeyBits(hint, pathSorter_->keys().grid().gpu);
        gpu::RtSerPush ser{push.frame, hint == KeyStrategy::None ? 0 : pathSorter_->keys().paramsAddress(),
                           bits > 16 ? bits - 16 : 0, std::min(bits, 16u)};
        rt_->serMegakernel(cmd, ser, hint, n);
      }
    });
  });
  if (detailedStats_ && !usesRt())
    addStep("counters", -1, [this](VkCommandBuffer cmd) {
      details_->recordWarps(cmd, buffers_->hitSteps.address(), buffers_->pathCount, 0, &timer_);
    });
  if (heatmapShown(settings_) != HeatmapView::None)
    addStep("heatmap", -1, [this](VkCommandBuffer cmd) { heatmap_->afterMegakernel(cmd, *buffers_, &timer_); });
}

// The bounce loop: trace, learn, shade, then keys, sort and reorder before the next bounce where the sort
// policy's plan says so (learn only for rays that were sorted). Trace and shade are dispatched indirectly
// over the live paths: all of them until a sort has moved the finished paths behind the live ones
// (GpuFrame::live); a bounce that does not sort keeps the last sort's order and live count.
// Settings::fusion folds the keys into shade and the reorder into the next trace: the stage times then
// report them as part of "shade" and "trace", since they are no longer passes of their own.
void PathTracer::buildWavefrontSteps(gpu::PathStagePush push) {
  addStep("generate", -1, [this, push](VkCommandBuffer cmd) {
    recordStage(cmd, &timer_, "generate", [&] { generate_.dispatchThreads(cmd, push, buffers_->pathCount); });
  });
  bool fusesGather = false;  // the last sort's reorder is left to this bounce's trace
  for (uint32_t b = 0; b < settings_.bounces; ++b) {
    push.bounce = b;
    if (loopsFrom(b, fusesGather)) {
      // The bounces left in one dispatch over the live paths (Settings::loopsBounces): nothing runs between them.
      addStep("trace+shade", static_cast<int>(b), [this, push](VkCommandBuffer cmd) {
        recordStage(cmd, &timer_, "trace+shade", [&] {
          shadeLoop_[traversalOf(settings_.bvh)].get().dispatchIndirect(cmd, push, buffers_->live.handle(), PathBuffers::kLiveDispatchOffset);
        });
      });
      return;
    }
    buildBounceSteps(b, push, fusesGather);
  }
}

bool PathTracer::countsSteps(int bounce) const {
  if (detailedStats_) return true;
  return bounce < 0 ? heatmapShown(settings_) != HeatmapView::None : heatmap_->readsAfterTrace(uint32_t(bounce));
}

// Whether bounces `bounce` to the last can run as shade.comp's bounce loop: Settings::loopsBounces, and each of
// them would fuse its trace and shade and sorts nothing after (so no later one gathers either).
bool PathTracer::loopsFrom(uint32_t bounce, bool fusesGather) const {
  if (!settings_.loopsBounces()) return false;
  for (uint32_t b = bounce; b < settings_.bounces; ++b) {
    const BouncePlan plan = planBounce(b, b == bounce && fusesGather);
    if (!plan.fusesTraceShade || plan.sortAfter) return false;
  }
  return true;
}

// shade.comp as bounce `bounce` needs it; `fusesTraceShade`: it also does the trace (Settings::traceShade).
// Settings::compaction: every shade but the last bounce's packs the live paths into the other state set and
// its own block of GpuFrame::live, which becomes the live block (the copy is timed as part of "shade"), and
// gives the slots it visited the dead key, so keys, sort and reorder after it see a live prefix with dead
// keys behind it as after a sort. Not where shade makes the keys (Settings::fusion keys): a path's key would
// have to go to its new slot, which another subgroup may be marking dead.
void PathTracer::recordShade(VkCommandBuffer cmd, const gpu::PathStagePush& push, uint32_t bounce, bool fusesTraceShade) {
  const bool sortAfter = settings_.sorts() && bounce + 1 < settings_.bounces && framePlan_.sortAfter[bounce];
  const bool keysInShade = sortAfter && settings_.fusesKeys();
  const bool compacts = settings_.compacts() && !keysInShade && bounce + 1 < settings_.bounces;
  const VkBuffer live = buffers_->live.handle();
  const VkDeviceSize liveDispatch = PathBuffers::kLiveDispatchOffset;
  if (usesRt()) {
    rt_->shade(cmd, push, buffers_->pathCount);
  } else if (compacts) {
    shade_[1][fusesTraceShade].get().dispatchIndirect(cmd, push, live, liveDispatch);
    computeBarrier(cmd);
    const VkBufferCopy packed{PathBuffers::liveAppendOffset(bounce), 0, PathBuffers::kLiveBlockBytes};
    copySizes(cmd, live, live, packed);
  } else {
    (keysInShade ? pathSorter_->shadeWithKeys() : shade_[0][fusesTraceShade].get())
        .dispatchIndirect(cmd, push, live, liveDispatch);
  }
}

PathTracer::BouncePlan PathTracer::planBounce(uint32_t b, bool fusesGather) const {
  BouncePlan p;
  const bool sorting = settings_.sorts();
  p.sortedBefore = sorting && b > 0 && framePlan_.sortAfter[b - 1];
  p.sortAfter = sorting && b + 1 < settings_.bounces && framePlan_.sortAfter[b];
  p.keysInShade = p.sortAfter && settings_.fusesKeys();
  p.compacts = settings_.compacts() && !p.keysInShade && b + 1 < settings_.bounces;
  p.learns = p.sortedBefore && strategyInfo(settings_.strategy).learnsLengths;
  // One dispatch for trace and shade where nothing between them reads the hits: no reorder in this trace,
  // no keys in shade, no learning from sorted rays, no detailed statistics, no heatmap of this bounce.
  p.fusesTraceShade = settings_.fusesTraceShade() && !fusesGather && !p.keysInShade && !p.learns && !detailedStats_ &&
                      !heatmap_->readsAfterTrace(b);
  return p;
}

void PathTracer::buildBounceSteps(uint32_t b, gpu::PathStagePush& push, bool& fusesGather) {
  const int bounce = static_cast<int>(b);
  const BouncePlan plan = planBounce(b, fusesGather);
  if (plan.fusesTraceShade) {
    addStep("trace+shade", bounce, [this, push, b](VkCommandBuffer cmd) {
      recordStage(cmd, &timer_, "trace+shade", [&] { recordShade(cmd, push, b, true); });
    });
  } else {
    buildTraceStep(b, push, fusesGather);
    if (fusesGather) push.stateSet = 1u - push.stateSet, fusesGather = false;
    if (detailedStats_ && !usesRt())
      addStep("counters", bounce, [this, b](VkCommandBuffer cmd) {
        details_->recordWarps(cmd, buffers_->hitSteps.address(), buffers_->pathCount, b, &timer_);
      });
    // Learning and the prediction figures are for rays that were keyed and sorted: other bounces have no
    // prediction to learn from or measure (their figures stay "not measured").
    if (plan.learns)
      addStep("learn", bounce, [this, push, b](VkCommandBuffer cmd) {
        pathSorter_->recordLearn(cmd, *buffers_, push.stateSet, b, &timer_);
      });
    if (plan.sortedBefore && detailedStats_)
      addStep("counters", bounce, [this, push, b](VkCommandBuffer cmd) {
        const KeyStage& keys = pathSorter_->keys();
        details_->recordPrediction(cmd, buffers_->frameBlock.address(), keys.paramsAddress(), push.stateSet,
                                   buffers_->pathCount, inverseDiagonal(keys.grid()), b, &timer_);
      });
    if (heatmap_->readsAfterTrace(b))
      addStep("heatmap", bounce, [this, push, b](VkCommandBuffer cmd) {
        heatmap_->afterTrace(cmd, *buffers_, push.stateSet, b, &timer_);
      });
    addStep("shade", bounce, [this, push, b](VkCommandBuffer cmd) {
      recordStage(cmd, &timer_, "shade", [&] { recordShade(cmd, push, b, false); });
    });
  }
  if (plan.compacts) push.stateSet = 1u - push.stateSet;
  if (plan.sortAfter) buildSortSteps(b, plan.keysInShade, push, fusesGather);
}

// The trace of bounce b alone: the rt pipeline, the gathering trace (it does the last sort's reorder), or the
// plain one over the live paths.
void PathTracer::buildTraceStep(uint32_t b, const gpu::PathStagePush& push, bool gathers) {
  addStep("trace", static_cast<int>(b), [this, push, gathers, b](VkCommandBuffer cmd) {
    const uint32_t n = buffers_->pathCount;
    recordStage(cmd, &timer_, "trace", [&] {
      if (usesRt())
        rt_->traceRays(cmd, push, n);  // every path; the shader skips those past the live count
      else if (gathers)
        trace_[settings_.countSimt][1][countsSteps(int(b))].get().dispatchThreads(cmd, push, n);  // every slot: it finds the live count
      else
        trace_[settings_.countSimt][0][countsSteps(int(b))].get()
            .dispatchIndirect(cmd, push, buffers_->live.handle(), PathBuffers::kLiveDispatchOffset);
    });
  });
}

void PathTracer::buildSortSteps(uint32_t b, bool keysInShade, gpu::PathStagePush& push, bool& fusesGather) {
  const int bounce = static_cast<int>(b);
  const bool heatmap = heatmapShown(settings_) != HeatmapView::None;
  addStep("keys", bounce, [this, push, b, keysInShade](VkCommandBuffer cmd) {
    pathSorter_->recordKeys(cmd, *buffers_, push.stateSet, b, keysInShade, &timer_);
  });
  // The keys made now sort the rays of the next bounce: their figures are that bounce's.
  if (detailedStats_)
    addStep("counters", bounce, [this, b](VkCommandBuffer cmd) {
      details_->recordDistinctKeys(cmd, buffers_->keys.address(), buffers_->pathCount,
                                   pathSorter_->keys().keyBits() - 1, b + 1, &timer_);
    });
  if (heatmap)
    addStep("heatmap", bounce, [this, push, b](VkCommandBuffer cmd) {
      heatmap_->afterKeys(cmd, *buffers_, push.stateSet, b, &timer_);
    });
  addStep("sort", bounce, [this](VkCommandBuffer cmd) { pathSorter_->recordSort(cmd, *buffers_, buffers_->pathCount, &timer_); });
  fusesGather = settings_.fusesGather() && !heatmap_->readsAfterSort(b);
  if (fusesGather) return;
  addStep("reorder", bounce, [this, push](VkCommandBuffer cmd) {
    pathSorter_->recordGather(cmd, *buffers_, buffers_->pathCount, push.stateSet, &timer_);
  });
  push.stateSet = 1u - push.stateSet;  // the gather's output set
  if (heatmap)
    addStep("heatmap", bounce, [this, push, b](VkCommandBuffer cmd) {
      heatmap_->afterSort(cmd, *buffers_, push.stateSet, b, &timer_);
    });
}

// Accumulate, tonemap (or the heatmap's colours), and the counters to the host.
void PathTracer::buildEndSteps(const gpu::PathStagePush& push) {
  addStep("accumulate", -1, [this, push](VkCommandBuffer cmd) {
    recordStage(cmd, &timer_, "accumulate", [&] { accumulate_.dispatchThreads(cmd, push, buffers_->pixelCount); });
  });
  addStep("tonemap", -1, [this, push](VkCommandBuffer cmd) {
    if (!heatmap_->colorize(cmd, *buffers_, &timer_))
      recordStage(cmd, &timer_, "tonemap", [&] { tonemap_.dispatchThreads(cmd, push, buffers_->pixelCount); });
  });
  addStep("counters", -1, [this](VkCommandBuffer cmd) {
    const KeyStage& keys = pathSorter_->keys();
    if (detailedStats_ && settings_.sorts() && keys.hasCache())
      details_->recordCacheUsed(cmd, keys.paramsAddress(), keys.cacheEntryCount(), &timer_);
    recordCountersToHost(cmd);
  });
}

}  // namespace raylab
