// The last measured point of every key strategy: how well it predicted where rays end (mean error, cell
// hit rate) against what it cost (trace, key+sort+reorder, frame time). Points are smoothed over the
// frames a strategy ran and forgotten when the scene, size or path length changes (no longer comparable).
#pragma once

#include <string>
#include <vector>

#include "renderer/frame_stats.h"
#include "renderer/settings.h"

namespace raylab {

struct StrategyPoint {
  KeyStrategy strategy = KeyStrategy::None;
  SortAlgorithm sort = SortAlgorithm::None;
  double traceMs = 0.0;
  double reorderMs = 0.0;      // learn + keys + sort + reorder: what reordering costs
  double frameMs = 0.0;
  double meanError = -1.0;     // -1: not measured (no spatial key, or detailed stats off)
  double cellHitRate = -1.0;
  uint32_t frames = 0;
};

class SpeedAccuracyBook {
 public:
  void record(const Settings& settings, const FrameStats& stats);
  const std::vector<StrategyPoint>& points() const { return points_; }
  const StrategyPoint* find(KeyStrategy s) const;

  // Weight of a new frame in the smoothed point.
  static constexpr double kSmoothing = 0.2;

 private:
  static bool comparable(const Settings& a, const Settings& b);
  std::vector<StrategyPoint> points_;
  Settings context_;
  KeyStrategy current_ = KeyStrategy::None;
  bool started_ = false;
};

}  // namespace raylab
