#include "ui/speed_accuracy_book.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "renderer/reorder/key_functions.h"
#include "renderer/reorder/key_strategies.h"
#include "renderer/settings/settings_table.h"
#include "renderer/stages.h"

namespace raylab {
namespace {

using Baseline = MethodKey::Baseline;

std::string number(const char* name, float v) {
  char text[48];
  if (std::isinf(v)) std::snprintf(text, sizeof(text), " %s inf", name);
  else std::snprintf(text, sizeof(text), " %s %g", name, v);
  return text;
}

bool hasStage(const FrameStats& stats, const char* name) {
  return std::any_of(stats.stages.begin(), stats.stages.end(), [&](const StageTime& t) { return t.stage == name; });
}

}  // namespace

MethodKey methodKeyOf(const Settings& s) {
  MethodKey k;
  k.kernel = s.kernel;
  k.tracer = s.tracer;
  if (s.tracer == Tracer::Compute) k.bvh = s.bvh;  // another trace, another method; rt has its own structure
  if (s.kernel == Kernel::Megakernel) {
    k.baseline = Baseline::Megakernel;
    if (s.reordersInHardware()) k.ser = s.ser;
    if (k.ser == Ser::Hint) k.strategy = s.strategy;  // the hint is the strategy's key
    return k;
  }
  if (s.tracer == Tracer::Compute) k.compaction = s.compaction;  // elsewhere it does nothing
  if (s.fusesTraceShade()) k.traceShade = s.traceShade;
  if (!s.sorts() || s.sortPolicy == SortPolicy::Never) {
    k.baseline = Baseline::Unsorted;
    return k;
  }
  k.strategy = s.strategy;
  k.sort = s.sort;
  k.policy = s.sortPolicy;
  if (s.strategy != KeyStrategy::DeadLast) {  // dead-last keys are 0 or dead: no grid
    k.grid = s.grid;
    if (s.grid.automatic) k.grid.cells = {0, 0, 0};
    else k.grid.autoCells = 0;
    k.clampDistance = s.clampToCamera ? s.clampDistance : 0.0f;
  } else {
    k.grid = GridSetting{false, 0, {0, 0, 0}};
  }
  if (strategyInfo(s.strategy).readsFixedLength) k.fixedFactor = s.fixedFactor;
  if (strategyInfo(s.strategy).readsEmaAlpha) k.emaAlpha = s.emaAlpha;
  if (strategyInfo(s.strategy).samplesGaussian) k.gaussOutlier = s.gaussOutlier, k.gaussReset = s.gaussReset;
  k.sortBits = s.sortBits;
  if (strategyInfo(s.strategy).learnsLengths) k.learnEvery = s.learnEvery;
  if (s.sorts() && s.tracer == Tracer::Compute) k.fusion = s.fusion;  // elsewhere it does nothing
  return k;
}

std::string describe(const MethodKey& k) {
  std::string tracer =
      std::string(k.tracer == Tracer::Rt ? " rt" : "") + (k.bvh != Settings{}.bvh ? " " + toString(k.bvh) : "");
  // The wavefront's own options where they differ from the default (unsorted and sorted alike).
  const std::string wavefront = (k.compaction != Settings{}.compaction ? " compaction " + toString(k.compaction) : "") +
                                (k.traceShade != Settings{}.traceShade ? " trace-shade " + toString(k.traceShade) : "");
  if (k.baseline == Baseline::Unsorted) return "unsorted" + tracer + wavefront;
  if (k.baseline == Baseline::Megakernel) {
    std::string text = "megakernel" + tracer;
    if (k.ser != Ser::Off) text += " ser-" + toString(k.ser);
    if (k.ser == Ser::Hint) text += " " + toString(k.strategy);
    return text;
  }
  std::string text = toString(k.strategy) + " " + toString(k.sort) + tracer;
  if (k.policy != SortPolicy::Always) text += " " + toString(k.policy);
  if (k.strategy != KeyStrategy::DeadLast) {
    char grid[48];
    if (k.grid.automatic) std::snprintf(grid, sizeof(grid), " | grid %u", k.grid.autoCells);
    else std::snprintf(grid, sizeof(grid), " | grid %ux%ux%u", k.grid.cells.x, k.grid.cells.y, k.grid.cells.z);
    text += grid;
    if (k.clampDistance > 0.0f) text += number("clamp", k.clampDistance);
  }
  if (strategyInfo(k.strategy).readsFixedLength) text += " |" + number("f", k.fixedFactor);
  if (strategyInfo(k.strategy).readsEmaAlpha) text += number("a", k.emaAlpha);
  if (strategyInfo(k.strategy).samplesGaussian) text += number("out", k.gaussOutlier) + number("reset", k.gaussReset);
  if (k.sortBits != 0) text += " | bits " + std::to_string(k.sortBits);
  if (k.learnEvery > 1) text += " | learn 1/" + std::to_string(k.learnEvery);
  if (k.fusion != Settings{}.fusion) text += " | fused " + toString(k.fusion);
  if (!wavefront.empty()) text += " |" + wavefront;
  return text;
}

void RecentMean::add(double v) {
  if (!(v >= 0.0)) return;  // -1 (not measured) and NaN
  values_[next_] = v;
  next_ = (next_ + 1) % kWindow;
  count_ = std::min(count_ + 1, kWindow);
}

double RecentMean::value() const {
  if (count_ == 0) return -1.0;
  double sum = 0.0;
  for (size_t i = 0; i < count_; ++i) sum += values_[i];
  return sum / double(count_);
}

bool SpeedAccuracyBook::comparable(const Settings& a, const Settings& b) {
  // Another scene is every setting the scene is made of (settings_table.h: the name, the room's seed, the
  // wide BVH's collapse, which orders the triangles and so the light samples).
  for (const SettingRow& r : settingRows())
    if ((r.effects & kEffectScene) && !r.same(a, b)) return false;
  return a.view == b.view && a.width == b.width && a.height == b.height && a.bounces == b.bounces &&
         a.sppPerFrame == b.sppPerFrame && a.countSimt == b.countSimt;
}

void SpeedAccuracyBook::clear() {
  points_.clear();
  nextNumber_ = 1;
}

const SpeedAccuracyPoint* SpeedAccuracyBook::find(const MethodKey& key) const {
  for (const SpeedAccuracyPoint& p : points_)
    if (p.key == key) return &p;
  return nullptr;
}

const SpeedAccuracyPoint* SpeedAccuracyBook::current() const { return started_ ? find(currentKey_) : nullptr; }

void SpeedAccuracyBook::dropOldest() {
  auto oldest = points_.end();
  for (auto it = points_.begin(); it != points_.end(); ++it)
    if (it->key.baseline == Baseline::None && !(it->key == currentKey_) &&
        (oldest == points_.end() || it->lastSeen < oldest->lastSeen))
      oldest = it;
  if (oldest != points_.end()) points_.erase(oldest);
}

void SpeedAccuracyBook::record(const Settings& rendered, const FrameStats& stats) {
  if (started_ && !comparable(rendered, context_)) clear();
  context_ = rendered;
  started_ = true;
  currentKey_ = methodKeyOf(rendered);
  auto it = std::find_if(points_.begin(), points_.end(), [&](const SpeedAccuracyPoint& p) { return p.key == currentKey_; });
  if (it == points_.end()) {
    SpeedAccuracyPoint fresh;
    fresh.number = nextNumber_++;
    fresh.key = currentKey_;
    fresh.label = describe(currentKey_);
    points_.push_back(fresh);
    it = points_.end() - 1;
  }
  SpeedAccuracyPoint& p = *it;
  ++p.frames;
  p.lastSeen = ++frame_;
  // A fused trace and shade has no trace time of its own to put on the axis.
  if (hasStage(stats, "trace") && !hasStage(stats, "trace+shade")) p.traceMs.add(stats.stageTotal("trace"));
  double reorderMs = 0.0;
  for (const StageInfo& st : kStages)
    if (isSortingCost(st.name)) reorderMs += stats.stageTotal(st.name);
  p.reorderMs.add(reorderMs);
  p.frameMs.add(stats.workMs());  // without the detailed statistics' own passes (on by default in the window)
  p.predictionError.add(meanOverBounces(stats.bounces, &BounceStats::predictionErrorMean, true));
  p.cellHitRate.add(meanOverBounces(stats.bounces, &BounceStats::cellHitRate, true));
  if (stats.traversalStatsUnavailable.empty())
    p.warpEfficiency.add(meanOverBounces(stats.bounces, &BounceStats::virtualWarpEfficiency, true));
  if (points_.size() > kMaxPoints) dropOldest();
}

}  // namespace raylab
