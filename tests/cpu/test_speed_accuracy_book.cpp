// The speed-accuracy book (ui/speed_accuracy_book.h) and the baseline run (ui/baseline_run.h): one point per
// method and parameter set, never mixed across parameter changes; baselines; the bench's accuracy figures.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "ui/baseline_run.h"
#include "ui/speed_accuracy_book.h"

namespace raylab {
namespace {

using Baseline = MethodKey::Baseline;

Settings sorted(KeyStrategy strategy) {
  Settings s;
  s.strategy = strategy;
  s.sort = SortAlgorithm::Radix;
  return s;
}

// A frame whose stages and per-bounce figures are given: bounce 0 never carries a prediction.
FrameStats frame(double traceMs, double frameMs, std::vector<double> errors = {}, std::vector<double> hits = {},
                 std::vector<double> warp = {}) {
  FrameStats f;
  f.frameMs = frameMs;
  f.stages = {{"generate", -1, 0.5}, {"trace", 0, traceMs / 2}, {"trace", 1, traceMs / 2}, {"keys", 0, 0.25},
              {"sort", 0, 0.5}, {"reorder", 0, 0.25}};
  size_t n = std::max({errors.size(), hits.size(), warp.size()});
  f.bounces.resize(n);
  for (size_t b = 0; b < n; ++b) {
    f.bounces[b].rays = 100;
    if (b < errors.size()) f.bounces[b].predictionErrorMean = errors[b];
    if (b < hits.size()) f.bounces[b].cellHitRate = hits[b];
    if (b < warp.size()) f.bounces[b].virtualWarpEfficiency = warp[b];
  }
  return f;
}

TEST(SpeedAccuracyBook, SameParametersAddToOnePoint) {
  SpeedAccuracyBook book;
  book.record(sorted(KeyStrategy::Fixed), frame(2.0, 10.0));
  book.record(sorted(KeyStrategy::Fixed), frame(4.0, 20.0));
  ASSERT_EQ(book.points().size(), 1u);
  const SpeedAccuracyPoint& p = book.points()[0];
  EXPECT_EQ(p.frames, 2u);
  EXPECT_DOUBLE_EQ(p.traceMs.value(), 3.0);
  EXPECT_DOUBLE_EQ(p.frameMs.value(), 15.0);
  EXPECT_DOUBLE_EQ(p.reorderMs.value(), 1.0);  // keys + sort + reorder
  EXPECT_EQ(book.current(), &p);
}

// Each parameter the strategy reads makes a new point, whose figures are its own frames' only.
TEST(SpeedAccuracyBook, ParameterChangeStartsANewUnsmoothedPoint) {
  struct Case {
    const char* what;
    KeyStrategy strategy;
    void (*change)(Settings&);
  };
  const Case cases[] = {
      {"grid cells", KeyStrategy::Fixed, [](Settings& s) { s.grid.autoCells = 32; }},
      {"explicit grid", KeyStrategy::Origin, [](Settings& s) { s.grid.automatic = false; }},
      {"clamp on", KeyStrategy::TwoPoint, [](Settings& s) { s.clampToCamera = true; }},
      {"fixed factor", KeyStrategy::Fixed, [](Settings& s) { s.fixedFactor = 0.25f; }},
      {"fixed factor (two-point)", KeyStrategy::TwoPoint, [](Settings& s) { s.fixedFactor = 0.25f; }},
      {"EMA alpha", KeyStrategy::Ema, [](Settings& s) { s.emaAlpha = 0.5f; }},
      {"Gaussian reset", KeyStrategy::Gaussian, [](Settings& s) { s.gaussReset = 5.0f; }},
      {"Gaussian outlier", KeyStrategy::Gaussian, [](Settings& s) { s.gaussOutlier = 2.0f; }},
      {"sort", KeyStrategy::Gaussian, [](Settings& s) { s.sort = SortAlgorithm::Bitonic; }},
      {"policy", KeyStrategy::Fixed, [](Settings& s) { s.sortPolicy = SortPolicy::Auto; }},
      {"sorted key bits", KeyStrategy::Fixed, [](Settings& s) { s.sortBits = 8; }},
      {"learning stride", KeyStrategy::Average, [](Settings& s) { s.learnEvery = 4; }},
      {"fusion", KeyStrategy::TwoPoint, [](Settings& s) { s.fusion = Fusion::Both; }},
      {"strategy", KeyStrategy::Fixed, [](Settings& s) { s.strategy = KeyStrategy::Average; }},
  };
  for (const Case& c : cases) {
    SpeedAccuracyBook book;
    Settings before = sorted(c.strategy), after = before;
    c.change(after);
    book.record(before, frame(2.0, 10.0, {-1, 0.1}, {-1, 0.9}));
    book.record(after, frame(6.0, 30.0, {-1, 0.3}, {-1, 0.5}));
    ASSERT_EQ(book.points().size(), 2u) << c.what;
    const SpeedAccuracyPoint& fresh = book.points()[1];
    EXPECT_NE(fresh.label, book.points()[0].label) << c.what;
    EXPECT_EQ(fresh.frames, 1u) << c.what;
    EXPECT_DOUBLE_EQ(fresh.traceMs.value(), 6.0) << c.what;
    EXPECT_DOUBLE_EQ(fresh.predictionError.value(), 0.3) << c.what;
    EXPECT_DOUBLE_EQ(fresh.cellHitRate.value(), 0.5) << c.what;
    EXPECT_DOUBLE_EQ(book.points()[0].traceMs.value(), 2.0) << c.what;
    // Coming back continues the first point.
    book.record(before, frame(4.0, 10.0));
    EXPECT_EQ(book.points().size(), 2u) << c.what;
    EXPECT_EQ(book.points()[0].frames, 2u) << c.what;
    EXPECT_EQ(book.current(), &book.points()[0]) << c.what;
  }
}

// Parameters a method does not read leave its point alone.
TEST(SpeedAccuracyBook, UnusedParametersDoNotSplitAPoint) {
  struct Case {
    const char* what;
    Settings settings;
    void (*change)(Settings&);
  };
  Settings unsorted;  // strategy none
  Settings mega = sorted(KeyStrategy::TwoPoint);
  mega.kernel = Kernel::Megakernel;
  const Case cases[] = {
      {"EMA alpha under fixed", sorted(KeyStrategy::Fixed), [](Settings& s) { s.emaAlpha = 0.9f; }},
      {"learning stride under fixed", sorted(KeyStrategy::Fixed), [](Settings& s) { s.learnEvery = 8; }},
      {"Gaussian reset under EMA", sorted(KeyStrategy::Ema), [](Settings& s) { s.gaussReset = 2.0f; }},
      {"factor under origin", sorted(KeyStrategy::Origin), [](Settings& s) { s.fixedFactor = 1.0f; }},
      {"grid under dead-last", sorted(KeyStrategy::DeadLast), [](Settings& s) { s.grid.autoCells = 8; }},
      {"clamp distance, clamp off", sorted(KeyStrategy::Fixed), [](Settings& s) { s.clampDistance = 7.0f; }},
      {"sort under strategy none", unsorted, [](Settings& s) { s.sort = SortAlgorithm::Bitonic; }},
      {"strategy under the megakernel", mega, [](Settings& s) { s.strategy = KeyStrategy::Fixed; }},
      {"heatmap and exposure", sorted(KeyStrategy::Fixed), [](Settings& s) { s.exposure = 3.0f, s.heatmap = HeatmapView::SortKey; }},
  };
  for (const Case& c : cases) {
    SpeedAccuracyBook book;
    Settings after = c.settings;
    c.change(after);
    book.record(c.settings, frame(2.0, 10.0));
    book.record(after, frame(2.0, 10.0));
    EXPECT_EQ(book.points().size(), 1u) << c.what;
  }
}

TEST(SpeedAccuracyBook, UnsortedAndMegakernelAreBaselines) {
  SpeedAccuracyBook book;
  Settings none;
  Settings noSort = sorted(KeyStrategy::Fixed);
  noSort.sort = SortAlgorithm::None;
  Settings never = sorted(KeyStrategy::TwoPoint);
  never.sortPolicy = SortPolicy::Never;
  Settings mega;
  mega.kernel = Kernel::Megakernel;
  for (const Settings& s : {none, noSort, never}) book.record(s, frame(3.0, 12.0));
  book.record(mega, FrameStats{.frameMs = 9.0, .stages = {{"megakernel", -1, 8.5}}});
  ASSERT_EQ(book.points().size(), 2u);
  EXPECT_EQ(book.points()[0].key.baseline, Baseline::Unsorted);
  EXPECT_EQ(book.points()[0].label, "unsorted");
  EXPECT_EQ(book.points()[0].frames, 3u);
  EXPECT_EQ(book.points()[1].key.baseline, Baseline::Megakernel);
  EXPECT_EQ(book.points()[1].label, "megakernel");
  EXPECT_LT(book.points()[1].traceMs.value(), 0.0);  // no trace stage: no point on the trace axis
  EXPECT_DOUBLE_EQ(book.points()[1].frameMs.value(), 9.0);
  EXPECT_EQ(book.find(methodKeyOf(sorted(KeyStrategy::Fixed))), nullptr);
}

// The bench's figures: the unweighted mean over bounces 1.. of those that measured it.
TEST(SpeedAccuracyBook, AccuracyIsTheBenchMetric) {
  SpeedAccuracyBook book;
  FrameStats f = frame(2.0, 10.0, {0.9, 0.2, 0.4, -1.0}, {0.9, 0.5, 0.7, -1.0}, {0.1, 0.6, 0.8, 0.7});
  f.bounces[2].rays = 1;  // weighting by rays would pull the mean towards bounce 1
  book.record(sorted(KeyStrategy::Fixed), f);
  const SpeedAccuracyPoint& p = book.points()[0];
  EXPECT_DOUBLE_EQ(p.predictionError.value(), 0.3);
  EXPECT_DOUBLE_EQ(p.predictionError.value(), meanOverBounces(f.bounces, &BounceStats::predictionErrorMean, true));
  EXPECT_DOUBLE_EQ(p.cellHitRate.value(), 0.6);
  EXPECT_DOUBLE_EQ(p.warpEfficiency.value(), 0.7);
  // A strategy with a prediction error but no cell-hit rate still has its error.
  book.record(sorted(KeyStrategy::TwoPoint), frame(2.0, 10.0, {-1, 0.25}, {}));
  EXPECT_DOUBLE_EQ(book.current()->predictionError.value(), 0.25);
  EXPECT_LT(book.current()->cellHitRate.value(), 0.0);
  // The rt tracer has no warp efficiency: not measured, never zero.
  Settings rt = sorted(KeyStrategy::Fixed);
  rt.tracer = Tracer::Rt;
  FrameStats r = frame(2.0, 10.0, {}, {}, {0.0, 0.0});
  r.traversalStatsUnavailable = "not available with the rt tracer";
  book.record(rt, r);
  EXPECT_LT(book.current()->warpEfficiency.value(), 0.0);
}

TEST(SpeedAccuracyBook, RecentMeanKeepsTheLastWindow) {
  RecentMean m;
  EXPECT_LT(m.value(), 0.0);
  m.add(-1.0);
  m.add(NAN);
  EXPECT_EQ(m.count(), 0u);
  for (size_t i = 0; i < RecentMean::kWindow; ++i) m.add(100.0);
  for (size_t i = 0; i < RecentMean::kWindow; ++i) m.add(2.0);
  EXPECT_DOUBLE_EQ(m.value(), 2.0);
  m.add(2.0 + RecentMean::kWindow);
  EXPECT_DOUBLE_EQ(m.value(), 3.0);
}

TEST(SpeedAccuracyBook, ContextChangeAndClearForgetPoints) {
  SpeedAccuracyBook book;
  Settings s = sorted(KeyStrategy::Fixed);
  book.record(s, frame(2.0, 10.0));
  book.record(Settings{}, frame(2.0, 10.0));
  EXPECT_EQ(book.points().size(), 2u);
  Settings bigger = s;
  bigger.width *= 2;
  book.record(bigger, frame(2.0, 10.0));  // another size: earlier costs do not compare
  ASSERT_EQ(book.points().size(), 1u);
  EXPECT_EQ(book.points()[0].number, 1);
  book.clear();
  EXPECT_TRUE(book.points().empty());
  EXPECT_EQ(book.current(), nullptr);
  book.record(bigger, frame(2.0, 10.0));
  EXPECT_EQ(book.points()[0].number, 1);
  // A setting the scene is made of (the room's seed, the wide collapse) is another scene: two methods' points
  // go, whatever the method of the next frame.
  Settings unsorted = bigger;
  unsorted.strategy = KeyStrategy::None;
  for (auto change : {+[](Settings& t) { t.clutterSeed += 1; },
                      +[](Settings& t) { t.wideCollapse = WideCollapse::Greedy; }}) {
    book.record(unsorted, frame(2.0, 10.0));
    ASSERT_EQ(book.points().size(), 2u);
    change(bigger);
    change(unsorted);
    book.record(bigger, frame(2.0, 10.0));
    EXPECT_EQ(book.points().size(), 1u);
    EXPECT_EQ(book.points()[0].number, 1);
  }
}

TEST(SpeedAccuracyBook, BoundedKeepingBaselinesAndTheCurrentPoint) {
  SpeedAccuracyBook book;
  book.record(Settings{}, frame(1.0, 5.0));  // the unsorted baseline, oldest of all
  Settings s = sorted(KeyStrategy::Fixed);
  for (int i = 0; i < 100; ++i) {
    s.fixedFactor = 0.01f * float(i + 1);  // a slider dragged through a hundred values
    book.record(s, frame(2.0, 10.0));
    ASSERT_LE(book.points().size(), SpeedAccuracyBook::kMaxPoints);
  }
  EXPECT_NE(book.find(methodKeyOf(Settings{})), nullptr);
  ASSERT_NE(book.current(), nullptr);
  EXPECT_EQ(book.current()->key, methodKeyOf(s));
  EXPECT_EQ(book.current()->number, 101);  // numbers are never reused
}

TEST(BaselineRun, MeasuresUnsortedThenMegakernelThenGivesTheMethodBack) {
  Settings user = sorted(KeyStrategy::Gaussian);
  user.gaussReset = 7.0f;
  Settings settings = user;
  BaselineRun run;
  SpeedAccuracyBook book;
  run.start(settings);
  int frames = 0;
  // The window: steer before drawing, render with what was asked, report the frame. A frame rendered
  // with older settings (one in flight) arrives first and must not count.
  Settings inFlight = settings;
  while (run.active() && frames < 100) {
    run.steer(settings);
    Settings rendered = inFlight;
    inFlight = settings;
    run.onFrame(rendered);
    book.record(rendered, frame(2.0, 10.0));
    ++frames;
  }
  EXPECT_FALSE(run.active());
  EXPECT_EQ(settings, user);  // the user's kernel and strategy back, nothing else touched
  const SpeedAccuracyPoint* unsorted = book.find(methodKeyOf(Settings{}));
  Settings mega;
  mega.kernel = Kernel::Megakernel;
  const SpeedAccuracyPoint* megakernel = book.find(methodKeyOf(mega));
  ASSERT_TRUE(unsorted && megakernel);
  EXPECT_GE(unsorted->frames, BaselineRun::kFrames);
  EXPECT_GE(megakernel->frames, BaselineRun::kFrames);
  EXPECT_LE(frames, int(2 * BaselineRun::kFrames + 4));
}

TEST(BaselineRun, CancelRestoresAtOnce) {
  Settings settings = sorted(KeyStrategy::Fixed);
  BaselineRun run;
  run.start(settings);
  run.steer(settings);
  EXPECT_EQ(settings.strategy, KeyStrategy::None);
  EXPECT_NE(run.status().find("unsorted"), std::string::npos);
  run.cancel(settings);
  EXPECT_FALSE(run.active());
  EXPECT_EQ(settings.strategy, KeyStrategy::Fixed);
  EXPECT_EQ(settings.kernel, Kernel::Wavefront);
}

// Compaction is a method of its own where the tracer compacts (the compute wavefront, sorted or not); the
// megakernel has nothing to compact, so its point stays the same.
TEST(SpeedAccuracyBook, CompactionIsAMethodWhereTheTracerCompacts) {
  auto key = [](Settings s, Compaction compaction) {
    s.compaction = compaction;
    return methodKeyOf(s);
  };
  Settings unsorted, sortedAlways = sorted(KeyStrategy::TwoPoint);
  EXPECT_EQ(describe(key(unsorted, Compaction::Shade)), "unsorted");  // the default
  EXPECT_EQ(describe(key(unsorted, Compaction::None)), "unsorted compaction none");
  EXPECT_NE(describe(key(sortedAlways, Compaction::Shade)), describe(key(sortedAlways, Compaction::None)));
  Settings mega = unsorted;
  mega.kernel = Kernel::Megakernel;
  EXPECT_EQ(key(mega, Compaction::Shade), key(mega, Compaction::None));
}

// The BVH layout is a method of its own with the compute tracer (another trace), for every kernel; the rt
// tracer walks its own structure, so there it splits no point.
TEST(SpeedAccuracyBook, BvhLayoutIsAMethodOfTheComputeTracer) {
  auto key = [](Settings s, BvhLayout bvh) {
    s.bvh = bvh;
    return methodKeyOf(s);
  };
  Settings unsorted, sortedAlways = sorted(KeyStrategy::TwoPoint), mega;
  mega.kernel = Kernel::Megakernel;
  EXPECT_EQ(describe(key(unsorted, BvhLayout::Sbvh)), "unsorted");  // the default
  EXPECT_EQ(describe(key(unsorted, BvhLayout::Wide)), "unsorted wide");
  EXPECT_EQ(describe(key(unsorted, BvhLayout::Binary)), "unsorted binary");
  EXPECT_EQ(describe(key(mega, BvhLayout::Binary)), "megakernel binary");
  EXPECT_NE(key(sortedAlways, BvhLayout::Binary), key(sortedAlways, BvhLayout::Wide));
  Settings rt = unsorted;
  rt.tracer = Tracer::Rt;
  EXPECT_EQ(key(rt, BvhLayout::Binary), key(rt, BvhLayout::Wide));
}

}  // namespace
}  // namespace raylab
