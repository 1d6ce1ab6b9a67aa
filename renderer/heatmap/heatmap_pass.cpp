#include "renderer/heatmap/heatmap_pass.h"

#include <algorithm>
#include <bit>

#include "renderer/heatmap/heatmap_rules.h"
#include "renderer/path_buffers.h"
#include "renderer/reorder/key_functions.h"
#include "renderer/vk/stage_timer.h"
#include "renderer/vk/vk_context.h"

namespace raylab {

// The shaders' view and key-colour ids are the enums' values, one for one (heatmap_types.h).
static_assert(static_cast<uint32_t>(HeatmapView::SortKey) == RL_HEAT_SORT_KEY);
static_assert(static_cast<uint32_t>(HeatmapView::CellHit) == RL_HEAT_CELL_HIT);
static_assert(static_cast<uint32_t>(HeatmapView::TraversalSteps) == RL_HEAT_STEPS);
static_assert(static_cast<uint32_t>(HeatmapView::WarpEfficiency) == RL_HEAT_WARP);
static_assert(static_cast<uint32_t>(HeatmapView::CacheMean) == RL_HEAT_CACHE_MEAN);
static_assert(static_cast<uint32_t>(HeatmapView::CacheVariance) == RL_HEAT_CACHE_VARIANCE);
static_assert(static_cast<uint32_t>(HeatmapKeyColour::Cell) == RL_HEAT_KEY_CELL);
static_assert(static_cast<uint32_t>(HeatmapKeyColour::Rank) == RL_HEAT_KEY_RANK);
static_assert(static_cast<uint32_t>(HeatmapKeyColour::Hash) == RL_HEAT_KEY_HASH);
static_assert(SettingLimits::kMaxGridCellsPerAxis <= (1u << RL_HEAT_CELL_BITS));

namespace {

// Views whose value goes through the ramp (and so take a scale and a locked range).
bool isScalar(HeatmapView v) {
  return v == HeatmapView::TraversalSteps || v == HeatmapView::WarpEfficiency || v == HeatmapView::CacheMean ||
         v == HeatmapView::CacheVariance;
}

const char* unitOf(HeatmapView view, HeatmapKeyColour keyColour) {
  switch (view) {
    case HeatmapView::SortKey: return keyColour == HeatmapKeyColour::Rank ? "rank among the sorted keys" : "sort key";
    case HeatmapView::CellHit: return "estimated cell = actual cell";
    case HeatmapView::TraversalSteps: return "traversal steps";
    case HeatmapView::WarpEfficiency: return "warp efficiency (W=32)";
    case HeatmapView::CacheMean: return "cached length mean";
    case HeatmapView::CacheVariance: return "cached length variance";
    default: return "";
  }
}

const char* noValueMeaningOf(HeatmapView view) {
  switch (view) {
    case HeatmapView::CellHit: return "escaped or no estimate";
    case HeatmapView::CacheMean:
    case HeatmapView::CacheVariance: return "no cache entry (unlearned or reset)";
    default: return "";
  }
}

}  // namespace

HeatmapPass::HeatmapPass(const VulkanContext& ctx, uint32_t pixelCount)
    : gather_(ctx, "heatmap_gather", sizeof(gpu::HeatmapPush), RL_PATH_GROUP_SIZE),
      colorize_(ctx, "heatmap_colorize", sizeof(gpu::HeatmapPush), RL_PATH_GROUP_SIZE),
      pixelCount_(pixelCount),
      heat_(ctx, VkDeviceSize(pixelCount) * 4),
      probeData_(ctx, VkDeviceSize(pixelCount) * 4 * RL_HEAT_PROBE_STRIDE),
      range_(ctx, 4 * RL_HEAT_RANGE_SLOTS, MemoryKind::HostVisible),
      probeReadback_(ctx, 4 * (1 + RL_HEAT_PROBE_STRIDE), MemoryKind::HostVisible) {}

void HeatmapPass::configure(const Settings& settings, VkDeviceAddress keyParams, const gpu::GpuKeyGrid* grid,
                            bool hasCache) {
  view_ = heatmapShown(settings);
  bounce_ = heatmapBounceShown(settings);
  width_ = settings.width;
  keyParams_ = keyParams;
  hasCache_ = hasCache;
  gathered_ = false;
  colouring_ = HeatmapColouring{};
  colouring_.view = view_;
  colouring_.keyColour = settings.heatmapKeyColour;
  colouring_.strategy = settings.strategy;
  colouring_.hasGrid = grid != nullptr && keyParams != 0;
  if (colouring_.hasGrid) colouring_.grid = *grid;
  colouring_.logScale = isScalar(view_) && settings.heatmapScale == HeatmapScale::Log;
  // Locked: the user's range; warp efficiency's natural range is 0..1; cell hits are 0 or 1. Otherwise the
  // frame's own range, read back by the colorize pass on the GPU.
  rangeFixed_ = true;
  if (isScalar(view_) && settings.heatmapRange.locked) {
    colouring_.lo = settings.heatmapRange.min, colouring_.hi = settings.heatmapRange.max;
  } else if (view_ == HeatmapView::WarpEfficiency || view_ == HeatmapView::CellHit) {
    colouring_.lo = 0.0f, colouring_.hi = 1.0f;
  } else {
    rangeFixed_ = false;
  }
}

void HeatmapPass::recordClear(VkCommandBuffer cmd) {
  if (view_ == HeatmapView::None) return;
  heat_.recordFill(cmd, RL_HEAT_EMPTY);
  // Minima start at the largest float (cells: the largest uint), maxima and counts at 0.
  const uint32_t clear[RL_HEAT_RANGE_SLOTS] = {0x7F7FFFFFu, 0u, 0u, 0u, ~0u, ~0u, ~0u, 0u, 0u, 0u};
  vkCmdUpdateBuffer(cmd, range_.handle(), 0, sizeof(clear), clear);
  computeBarrier(cmd);
}

gpu::HeatmapPush HeatmapPass::push(const PathBuffers& buffers, uint32_t stateSet, uint32_t gatherKind,
                                   bool megakernel) const {
  gpu::HeatmapPush p{};
  p.frame = buffers.frameBlock.address();
  p.keyParams = megakernel ? 0 : keyParams_;
  p.keys = buffers.keys.address();
  p.heat = heat_.address();
  p.probe = probeData_.address();
  p.range = range_.address();
  p.view = static_cast<uint32_t>(view_);
  p.stateSet = stateSet;
  p.megakernel = megakernel ? 1u : 0u;
  p.hasKeyParams = p.keyParams != 0 ? 1u : 0u;
  p.hasCache = p.keyParams != 0 && hasCache_ ? 1u : 0u;
  p.gather = gatherKind;
  p.keyColour = static_cast<uint32_t>(colouring_.keyColour);
  p.strategy = strategyId(colouring_.strategy);
  p.logScale = colouring_.logScale ? 1u : 0u;
  p.rangeFixed = rangeFixed_ ? 1u : 0u;
  p.rangeMin = colouring_.lo;
  p.rangeMax = colouring_.hi;
  return p;
}

void HeatmapPass::gather(VkCommandBuffer cmd, const PathBuffers& buffers, uint32_t stateSet, uint32_t gatherKind,
                         bool megakernel, StageTimer* timer) {
  ScopedStage s(timer, cmd, "heatmap");
  gather_.get().dispatchThreads(cmd, push(buffers, stateSet, gatherKind, megakernel), buffers.pathCount);
  computeBarrier(cmd);
  gathered_ = true;
}

bool HeatmapPass::readsAfterTrace(uint32_t bounce) const {
  return view_ != HeatmapView::None && view_ != HeatmapView::SortKey && bounce == bounce_;
}

void HeatmapPass::afterTrace(VkCommandBuffer cmd, const PathBuffers& buffers, uint32_t stateSet, uint32_t bounce,
                             StageTimer* timer) {
  if (readsAfterTrace(bounce)) gather(cmd, buffers, stateSet, RL_HEAT_GATHER_VALUE, false, timer);
}

void HeatmapPass::afterKeys(VkCommandBuffer cmd, const PathBuffers& buffers, uint32_t stateSet, uint32_t bounce,
                            StageTimer* timer) {
  if (view_ == HeatmapView::SortKey && bounce + 1 == bounce_)
    gather(cmd, buffers, stateSet, RL_HEAT_GATHER_VALUE, false, timer);
}

bool HeatmapPass::readsAfterSort(uint32_t bounce) const {
  return view_ == HeatmapView::SortKey && colouring_.keyColour == HeatmapKeyColour::Rank && bounce + 1 == bounce_;
}

void HeatmapPass::afterSort(VkCommandBuffer cmd, const PathBuffers& buffers, uint32_t sortedSet, uint32_t bounce,
                            StageTimer* timer) {
  if (readsAfterSort(bounce)) gather(cmd, buffers, sortedSet, RL_HEAT_GATHER_RANK, false, timer);
}

void HeatmapPass::afterMegakernel(VkCommandBuffer cmd, const PathBuffers& buffers, StageTimer* timer) {
  // Only per-path totals exist after a megakernel: the whole path's traversal steps.
  if (view_ == HeatmapView::TraversalSteps || view_ == HeatmapView::WarpEfficiency)
    gather(cmd, buffers, 0, RL_HEAT_GATHER_VALUE, true, timer);
}

bool HeatmapPass::colorize(VkCommandBuffer cmd, const PathBuffers& buffers, StageTimer* timer) {
  probeRecorded_.reset();
  if (view_ == HeatmapView::None) return false;
  ScopedStage s(timer, cmd, "heatmap");
  colorize_.get().dispatchThreads(cmd, push(buffers, 0, RL_HEAT_GATHER_VALUE, false), buffers.pixelCount);
  computeBarrier(cmd);
  // The hovered pixel: its heat word and probe words, 16 bytes (the caller's end-of-frame barrier makes
  // them visible to the host).
  if (probe_ && width_ > 0) {
    const VkDeviceSize pixel = VkDeviceSize(probe_->y) * width_ + probe_->x;
    if (probe_->x < width_ && pixel < pixelCount_) {
      const VkBufferCopy value{pixel * 4, 0, 4};
      const VkBufferCopy probe{pixel * 4 * RL_HEAT_PROBE_STRIDE, 4, 4 * RL_HEAT_PROBE_STRIDE};
      vkCmdCopyBuffer(cmd, heat_.handle(), probeReadback_.handle(), 1, &value);
      vkCmdCopyBuffer(cmd, probeData_.handle(), probeReadback_.handle(), 1, &probe);
      probeRecorded_ = probe_;
    }
  }
  return true;
}

void HeatmapPass::finishFrame(FrameStats& stats) {
  HeatmapStats& h = stats.heatmap;
  h = HeatmapStats{};
  if (view_ == HeatmapView::None) return;
  const auto* r = static_cast<const uint32_t*>(range_.mapped());
  const bool sortKey = view_ == HeatmapView::SortKey;
  const bool ranks = sortKey && colouring_.keyColour == HeatmapKeyColour::Rank;
  h.view = toString(view_);
  h.bounce = bounce_;
  h.unit = unitOf(view_, colouring_.keyColour);
  h.keyColour = sortKey ? toString(colouring_.keyColour) : "";
  h.scale = sortKey && !ranks ? "categorical" : colouring_.logScale ? "log" : "linear";
  h.pixels = pixelCount_;
  h.pixelsWithValue = r[RL_HEAT_RANGE_VALUES];
  h.pixelsWithoutValue = r[RL_HEAT_RANGE_NO_VALUE];
  h.pixelsWithoutPath = pixelCount_ - std::min(pixelCount_, h.pixelsWithValue + h.pixelsWithoutValue);
  h.noValueMeaning = noValueMeaningOf(view_);
  if (r[RL_HEAT_RANGE_MIN] <= r[RL_HEAT_RANGE_MAX]) {  // something was written
    const bool keyBits = sortKey && !ranks;
    h.frameMin = keyBits ? double(r[RL_HEAT_RANGE_MIN]) : double(std::bit_cast<float>(r[RL_HEAT_RANGE_MIN]));
    h.frameMax = keyBits ? double(r[RL_HEAT_RANGE_MAX]) : double(std::bit_cast<float>(r[RL_HEAT_RANGE_MAX]));
  }
  for (int a = 0; a < 3; ++a)
    colouring_.cellLo[a] = r[RL_HEAT_RANGE_CELL_MIN + a], colouring_.cellHi[a] = r[RL_HEAT_RANGE_CELL_MAX + a];
  h.rangeLocked = rangeFixed_;
  if (!rangeFixed_) colouring_.lo = float(h.frameMin), colouring_.hi = float(h.frameMax);
  h.min = rangeFixed_ ? colouring_.lo : h.frameMin;
  h.max = rangeFixed_ ? colouring_.hi : h.frameMax;
  if (!gathered_)
    h.emptyReason = sortKey ? "no keys were made for bounce " + std::to_string(bounce_) +
                                  " this frame: the sort policy did not sort after bounce " + std::to_string(bounce_ - 1)
                            : "no gather ran for bounce " + std::to_string(bounce_) + " this frame";
  else if (h.pixelsWithValue + h.pixelsWithoutValue == 0)
    h.emptyReason = "no path reached bounce " + std::to_string(bounce_) + " (all finished earlier)";
  if (probeRecorded_) {
    const auto* p = static_cast<const uint32_t*>(probeReadback_.mapped());
    HeatmapProbe& q = h.probe;
    q.valid = true;
    q.x = probeRecorded_->x, q.y = probeRecorded_->y;
    const uint32_t heat = p[0], id = p[1 + RL_HEAT_PROBE_PATH], key = p[1 + RL_HEAT_PROBE_KEY],
                   cell = p[1 + RL_HEAT_PROBE_CELL];
    q.state = heat == RL_HEAT_EMPTY ? "no path at this bounce" : heat == RL_HEAT_NO_VALUE ? h.noValueMeaning : "value";
    q.value = heat >= RL_HEAT_NO_VALUE ? 0.0 : sortKey && !ranks ? double(heat) : double(std::bit_cast<float>(heat));
    q.hasPath = heat != RL_HEAT_EMPTY && id != RL_DEAD_PATH;
    q.pathId = id;
    q.hasKey = q.hasPath && key != RL_DEAD_KEY;
    q.key = key;
    q.hasCell = q.hasPath && cell != RL_HEAT_NO_CELL;
    const bool direction = sortKey && colouring_.strategy == KeyStrategy::Direction;
    const uint32_t mask = (1u << RL_HEAT_CELL_BITS) - 1;
    q.cell = direction ? glm::uvec3(cell & 0xFFFFu, cell >> 16, 0)
                       : glm::uvec3(cell & mask, (cell >> RL_HEAT_CELL_BITS) & mask, cell >> (2 * RL_HEAT_CELL_BITS));
    q.cellKind = direction ? "direction cell" : sortKey ? "key cell" : "origin cell";
    q.octant = p[1 + RL_HEAT_PROBE_OCTANT];
  }
}

std::vector<uint32_t> HeatmapPass::readValues() const { return heat_.downloadVector<uint32_t>(pixelCount_); }

std::vector<uint32_t> HeatmapPass::readProbes() const {
  return probeData_.downloadVector<uint32_t>(size_t(pixelCount_) * RL_HEAT_PROBE_STRIDE);
}

}  // namespace raylab
