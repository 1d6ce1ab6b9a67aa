#include "ui/speed_accuracy_book.h"

#include <algorithm>

namespace raylab {
namespace {

// Ray-weighted mean over the bounces that measured it; -1 when none did.
template <class Get>
double weightedMean(const FrameStats& stats, Get get) {
  double sum = 0.0, weight = 0.0;
  for (const BounceStats& b : stats.bounces) {
    double v = get(b);
    if (v < 0.0) continue;
    sum += v * b.rays;
    weight += b.rays;
  }
  return weight > 0.0 ? sum / weight : -1.0;
}

double smooth(double old, double fresh, uint32_t frames) {
  if (fresh < 0.0) return old;
  if (frames == 0 || old < 0.0) return fresh;
  return old + SpeedAccuracyBook::kSmoothing * (fresh - old);
}

}  // namespace

bool SpeedAccuracyBook::comparable(const Settings& a, const Settings& b) {
  return a.scene == b.scene && a.width == b.width && a.height == b.height && a.bounces == b.bounces &&
         a.sppPerFrame == b.sppPerFrame && a.kernel == b.kernel && a.countSimt == b.countSimt;
}

const StrategyPoint* SpeedAccuracyBook::find(KeyStrategy s) const {
  for (const StrategyPoint& p : points_)
    if (p.strategy == s) return &p;
  return nullptr;
}

void SpeedAccuracyBook::record(const Settings& settings, const FrameStats& stats) {
  if (started_ && !comparable(settings, context_)) points_.clear();
  context_ = settings;
  started_ = true;
  auto it = std::find_if(points_.begin(), points_.end(), [&](const StrategyPoint& p) { return p.strategy == settings.strategy; });
  if (it == points_.end()) it = points_.insert(points_.end(), StrategyPoint{settings.strategy});
  StrategyPoint& p = *it;
  if (current_ != settings.strategy || p.sort != settings.sort) p.frames = 0;  // coming back: a fresh point
  current_ = settings.strategy;
  p.sort = settings.sort;
  double reorder = stats.stageTotal("learn") + stats.stageTotal("keys") + stats.stageTotal("sort") +
                   stats.stageTotal("reorder") + stats.stageTotal("oracle-trace");
  p.traceMs = smooth(p.traceMs, stats.stageTotal("trace"), p.frames);
  p.reorderMs = smooth(p.reorderMs, reorder, p.frames);
  p.frameMs = smooth(p.frameMs, stats.frameMs, p.frames);
  double error = weightedMean(stats, [](const BounceStats& b) { return b.predictionErrorMean; });
  double hits = weightedMean(stats, [](const BounceStats& b) { return b.cellHitRate; });
  p.meanError = p.frames == 0 ? error : smooth(p.meanError, error, p.frames);
  p.cellHitRate = p.frames == 0 ? hits : smooth(p.cellHitRate, hits, p.frames);
  ++p.frames;
}

}  // namespace raylab
