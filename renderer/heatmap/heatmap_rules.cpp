#include "renderer/heatmap/heatmap_rules.h"

#include <algorithm>

#include "renderer/reorder/key_functions.h"
#include "renderer/reorder/key_strategies.h"

namespace raylab {
namespace {

// Strategies that estimate where a ray ends (the cell-hit view compares that cell with the actual one): those
// that read a length, fixed or learned.
bool predictsLength(KeyStrategy k) { return strategyInfo(k).readsFixedLength; }

}  // namespace

uint32_t heatmapBounceShown(const Settings& s) {
  return std::min(s.heatmapBounce, s.bounces > 0 ? s.bounces - 1 : 0u);
}

std::optional<std::string> heatmapUnavailable(const Settings& s, HeatmapView view) {
  // Traversal steps and warp efficiency come from the trace itself, which every kernel runs.
  if (view == HeatmapView::None || view == HeatmapView::TraversalSteps || view == HeatmapView::WarpEfficiency)
    return std::nullopt;
  const std::string name = toString(view);
  if (s.kernel == Kernel::Megakernel)
    return name + " needs the wavefront kernel: the megakernel computes no sort keys or length estimates";
  if (s.strategy == KeyStrategy::None) return name + " needs a key strategy: strategy none computes no keys";
  if (s.sort == SortAlgorithm::None) return name + " needs a sort (bitonic or radix): sort none runs no key stage";
  if (s.sortPolicy == SortPolicy::Never && view != HeatmapView::CacheMean && view != HeatmapView::CacheVariance)
    return name + " needs sorted bounces: sort policy never runs no key stage";
  if (view == HeatmapView::CellHit && !predictsLength(s.strategy))
    return name + ": strategy " + toString(s.strategy) + " estimates no ray length, so there is no estimated cell";
  if ((view == HeatmapView::CacheMean || view == HeatmapView::CacheVariance) && !strategyInfo(s.strategy).learnsLengths)
    return name + ": strategy " + toString(s.strategy) +
           " keeps no length cache (only average, ema and gaussian learn one)";
  if (heatmapBounceShown(s) == 0)
    return name + ": camera rays (bounce 0) get no keys; show bounce 1 or later (needs 2 or more bounces)";
  return std::nullopt;
}

HeatmapView heatmapShown(const Settings& s) { return heatmapUnavailable(s) ? HeatmapView::None : s.heatmap; }

}  // namespace raylab
