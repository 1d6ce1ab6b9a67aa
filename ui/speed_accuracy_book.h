// The speed-accuracy book: one point per method and parameter set (key strategy, sort, policy, grid, clamp,
// the strategy's own length parameters; or a baseline: the unsorted wavefront, the megakernel), each with
// what it cost (trace, reorder, frame time) and how well it predicted where rays end (the bench's
// prediction error and cell-hit rate) and how coherent the warps were. A frame adds to the point of the
// parameters it was rendered with, so changing a slider starts a new point instead of smoothing the old one
// into it; coming back to earlier parameters continues their point (same method, comparable frames).
// Plain C++ (no ImGui): the panel draws it, tests/cpu/test_speed_accuracy_book.cpp checks it.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "renderer/frame_stats.h"
#include "renderer/settings/settings.h"

namespace raylab {

// The settings that make a method, with what the method does not read cleared, so that (say) an EMA
// alpha moved while the strategy is `fixed` does not split its point. Unsorted wavefronts (no strategy, no
// sort or policy never) are one method, as are megakernels (they never sort; SER's hint reads the strategy).
struct MethodKey {
  enum class Baseline { None, Unsorted, Megakernel };
  Baseline baseline = Baseline::None;
  Kernel kernel = Kernel::Wavefront;
  Tracer tracer = Tracer::Compute;
  BvhLayout bvh = Settings{}.bvh;  // Settings::bvh with the compute tracer (the default with rt)
  Ser ser = Ser::Off;
  KeyStrategy strategy = KeyStrategy::None;
  SortAlgorithm sort = SortAlgorithm::None;
  SortPolicy policy = SortPolicy::Always;
  GridSetting grid;
  float clampDistance = 0.0f;  // 0: the grid is not clamped to the camera
  float fixedFactor = 0.0f;
  float emaAlpha = 0.0f;
  float gaussOutlier = 0.0f;
  float gaussReset = 0.0f;
  uint32_t sortBits = 0;    // Settings::sortBits (0: all)
  uint32_t learnEvery = 0;  // Settings::learnEvery of a length-cache strategy; 0 without a cache
  Fusion fusion = Settings{}.fusion;  // Settings::fusion where the tracer applies it (the default elsewhere)
  // Settings::compaction where the tracer applies it (the compute wavefront; the default elsewhere).
  Compaction compaction = Settings{}.compaction;
  TraceShade traceShade = Settings{}.traceShade;  // Settings::traceShade where the tracer applies it
  bool operator==(const MethodKey&) const = default;
};

MethodKey methodKeyOf(const Settings& settings);
// Short and unique per key: "two-point radix | grid 64 | f 0.5", "unsorted", "megakernel rt ser-on".
std::string describe(const MethodKey& key);

// Mean of the last kWindow values added (values < 0, "not measured", are not added): recent enough for an
// adaptive strategy that is still learning, long enough to calm a CPU device's frame-to-frame jumps.
class RecentMean {
 public:
  static constexpr size_t kWindow = 32;
  void add(double v);
  double value() const;  // -1 before any value
  size_t count() const { return count_; }

 private:
  std::array<double, kWindow> values_{};
  size_t next_ = 0, count_ = 0;
};

struct SpeedAccuracyPoint {
  int number = 0;  // 1, 2, ... in order of appearance, never reused until Clear: the plot's labels
  MethodKey key;
  std::string label;  // describe(key)
  uint32_t frames = 0;
  RecentMean traceMs;          // trace stage, all bounces (not for megakernels: they have none)
  RecentMean reorderMs;        // learn + keys + sort + reorder + oracle-trace: what reordering costs
  RecentMean frameMs;          // GPU frame time
  RecentMean predictionError;  // meanOverBounces(predictionErrorMean, from bounce 1): bench's prediction_error_mean
  RecentMean cellHitRate;      // likewise cell_hit_rate
  RecentMean warpEfficiency;   // virtual warp efficiency from bounce 1 (virtual_warp_efficiency_after_first)
  uint64_t lastSeen = 0;       // the book's frame counter when this point last got a frame
};

class SpeedAccuracyBook {
 public:
  // Beyond this many points the least recently measured non-baseline point goes (a slider dragged through
  // a hundred values must not grow the book, or the table, without bound).
  static constexpr size_t kMaxPoints = 40;

  // Adds a finished frame to the point of the settings it was rendered with. A different scene (or a setting
  // it is made of: the room's seed, the wide collapse), view, size, path length, samples per frame or SIMT
  // counting makes earlier points incomparable: they go.
  void record(const Settings& rendered, const FrameStats& stats);
  void clear();
  const std::vector<SpeedAccuracyPoint>& points() const { return points_; }
  const SpeedAccuracyPoint* find(const MethodKey& key) const;
  const SpeedAccuracyPoint* current() const;  // the point of the last recorded frame

 private:
  static bool comparable(const Settings& a, const Settings& b);
  void dropOldest();
  std::vector<SpeedAccuracyPoint> points_;
  Settings context_;
  bool started_ = false;
  int nextNumber_ = 1;
  uint64_t frame_ = 0;
  MethodKey currentKey_;
};

}  // namespace raylab
