// `raylab study`'s plan (app/study/study_plan.h) is a pure function of its options and preset, and its K shards
// (K = 2, 3) are disjoint and together the whole plan: every (size, bench cell) in exactly one shard.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <utility>
#include <vector>

#include "app/cli_options.h"
#include "app/study/study_plan.h"

namespace raylab {
namespace {

StudyOptions studyOptionsFor(BenchShard shard) {
  StudyOptions o;
  o.target = "temple@hall";
  o.outDir = "out";
  o.sizes = {"32x16", "64x32", "48x24"};
  o.strategies = "fixed,two-point";
  o.shard = shard;
  return o;
}

// The bench arguments without --shard: what every shard of a study shares.
std::vector<std::string> withoutShard(std::vector<std::string> args) {
  takeShard(args);
  return args;
}

TEST(StudyPlan, IsAPureFunctionOfItsOptions) {
  const StudyPreset preset = studyPreset(/*quick=*/false, /*cpuDevice=*/true);
  EXPECT_EQ(preset.sizes, studyPreset(false, true).sizes);
  const std::vector<StudySize> a = studyPlan(studyOptionsFor({}), preset), b = studyPlan(studyOptionsFor({}), preset);
  ASSERT_EQ(a.size(), 3u);
  ASSERT_EQ(b.size(), 3u);
  size_t first = 0;
  for (size_t s = 0; s < a.size(); ++s) {
    EXPECT_EQ(a[s].size, b[s].size);
    EXPECT_EQ(a[s].benchArgs, b[s].benchArgs);
    EXPECT_EQ(a[s].cells, b[s].cells);
    EXPECT_GT(a[s].cells, 3u);
    EXPECT_EQ(a[s].firstCell, first);
    EXPECT_TRUE(a[s].benchShard.whole());
    EXPECT_EQ(a[s].shardCells(), a[s].cells);
    EXPECT_EQ(a[s].folder, "out/size-" + a[s].size);
    first += a[s].cells;
  }
  EXPECT_EQ(a[0].size, "32x16");  // --sizes' order is the plan's
  EXPECT_EQ(a[2].size, "48x24");
  // The preset fills what the options leave out.
  StudyOptions bare;
  bare.target = "cornell";
  const std::vector<StudySize> p = studyPlan(bare, studyPreset(true, false));
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p[0].size, "512x256");
  EXPECT_EQ(p[2].size, "4096x2048");
}

TEST(StudyPlan, ShardsAreDisjointAndCoverThePlan) {
  const StudyPreset preset = studyPreset(false, true);
  const std::vector<StudySize> whole = studyPlan(studyOptionsFor({}), preset);
  for (uint32_t k : {2u, 3u}) {
    std::set<std::pair<std::string, size_t>> seen;  // (size, bench cell)
    size_t total = 0, studyCells = 0;
    for (const StudySize& s : whole) studyCells += s.cells;
    for (uint32_t i = 0; i < k; ++i) {
      const std::vector<StudySize> shard = studyPlan(studyOptionsFor({i, k}), preset);
      ASSERT_EQ(shard.size(), whole.size());
      size_t own = 0;
      for (size_t s = 0; s < shard.size(); ++s) {
        EXPECT_EQ(withoutShard(shard[s].benchArgs), whole[s].benchArgs) << "only --shard differs";
        EXPECT_EQ(shard[s].cells, whole[s].cells);
        EXPECT_EQ(shard[s].benchShard.count, k);
        for (size_t n = 0; n < shard[s].cells; ++n) {
          if (!shard[s].benchShard.contains(n)) continue;
          EXPECT_TRUE(seen.emplace(shard[s].size, n).second) << shard[s].size << " cell " << n << " in two shards";
          EXPECT_EQ((shard[s].firstCell + n) % k, i) << "study cell g goes to shard g mod K";
          ++own;
        }
        std::vector<std::string> args = shard[s].benchArgs;
        EXPECT_EQ(takeShard(args), shard[s].benchShard) << "the bench is told its shard";
      }
      // Round robin over the whole study: the shards differ by at most one cell.
      EXPECT_LE(own, (studyCells + k - 1) / k);
      EXPECT_GE(own, studyCells / k);
      total += own;
    }
    EXPECT_EQ(total, studyCells) << "K=" << k;
    EXPECT_EQ(seen.size(), studyCells) << "K=" << k;
  }
}

}  // namespace
}  // namespace raylab

namespace raylab {
namespace {

// --quick says what it changes (issue 34): on a CPU device it drops the fixed keys, and says so.
TEST(StudyPlan, QuickSaysWhatItChanges) {
  const std::string cpu = quickText(/*cpuDevice=*/true), gpu = quickText(false);
  EXPECT_NE(cpu.find("--quick on a CPU device: " + presetText(studyPreset(true, true))), std::string::npos) << cpu;
  EXPECT_NE(cpu.find("it drops the strategies fixed"), std::string::npos) << cpu;
  EXPECT_NE(gpu.find("it drops the strategies dead-last, average"), std::string::npos) << gpu;
  EXPECT_NE(presetText(studyPreset(true, true)).find("2 timed frames after 1 warm-up; 3 rounds"), std::string::npos);
}

// Every size's bench gets the preset's rounds, or --rounds's.
TEST(StudyPlan, RoundsReachEveryBench) {
  StudyOptions o;
  o.target = "cornell";
  o.sizes = {"32x16", "64x32"};
  auto roundsOf = [](const std::vector<std::string>& args) {
    for (size_t i = 0; i + 1 < args.size(); ++i)
      if (args[i] == "--rounds") return args[i + 1];
    return std::string();
  };
  for (const StudySize& s : studyPlan(o, studyPreset(false, true))) EXPECT_EQ(roundsOf(s.benchArgs), "3");
  o.rounds = "5";
  for (const StudySize& s : studyPlan(o, studyPreset(false, true))) EXPECT_EQ(roundsOf(s.benchArgs), "5");
}

}  // namespace
}  // namespace raylab

namespace raylab {
namespace {

std::string valueOf(const std::vector<std::string>& args, const std::string& flag) {
  for (size_t i = 0; i + 1 < args.size(); ++i)
    if (args[i] == flag) return args[i + 1];
  return {};
}

// The motion section's sweeps (issue 37): one bench along each built-in path of the scene (the view left out:
// a path sets the camera), at the largest size up to kMotionMaxPaths, the first bounce count, the preset's
// path-frame cap; a given --camera-path replaces them; a sharded study has none.
TEST(StudyPlan, MotionSweepsReplayEveryBuiltinPath) {
  StudyOptions o;
  o.target = "temple@hall";
  o.outDir = "out";
  o.sizes = {"32x16", "4096x2048", "2048x1024", "64x32"};
  o.bounces = "3,5";
  o.strategies = "two-point";
  const StudyPreset quick = studyPreset(/*quick=*/true, /*cpuDevice=*/true);
  const std::vector<std::string> paths = studyMotionPaths(o);
  EXPECT_EQ(paths, (std::vector<std::string>{"builtin:orbit", "builtin:walk", "builtin:cut"}));
  const std::vector<StudyMotion> plan = studyMotionPlan(o, quick, paths);
  ASSERT_EQ(plan.size(), 3u);
  for (size_t i = 0; i < plan.size(); ++i) {
    const std::vector<std::string>& a = plan[i].benchArgs;
    EXPECT_EQ(valueOf(a, "--camera-path"), paths[i]);
    EXPECT_EQ(valueOf(a, "--cases"), "temple");
    EXPECT_EQ(valueOf(a, "--size"), "2048x1024");
    EXPECT_EQ(valueOf(a, "--bounces"), "3");
    EXPECT_EQ(valueOf(a, "--strategies"), "two-point");
    EXPECT_EQ(valueOf(a, "--sort-policies"), "always,auto");
    EXPECT_EQ(valueOf(a, "--frames"), quick.pathFrames);
    EXPECT_EQ(valueOf(a, "--out-dir"), plan[i].folder);
  }
  EXPECT_EQ(plan[2].folder, "out/motion-cut");
  EXPECT_TRUE(valueOf(studyMotionPlan(o, studyPreset(false, false), paths)[0].benchArgs, "--frames").empty())
      << "the full GPU study replays whole paths";
  // Every size above kMotionMaxPaths: the smallest of them.
  o.sizes = {"4096x2048", "2560x2048"};
  EXPECT_EQ(valueOf(studyMotionPlan(o, quick, paths)[0].benchArgs, "--size"), "2560x2048");

  o.cameraPath = "builtin:walk";
  EXPECT_EQ(studyMotionPaths(o), (std::vector<std::string>{"builtin:walk"}));
  o.shard = BenchShard{1, 2};
  EXPECT_TRUE(studyMotionPlan(o, quick, studyMotionPaths(o)).empty()) << "bench --merge keeps no path frames";
}

TEST(StudyPlan, AMissingPathFileIsAUsageError) {
  StudyOptions o;
  o.target = "cornell";
  o.cameraPath = "/nonexistent/walk.json";
  EXPECT_THROW(studyMotionPaths(o), UsageError);
  o.cameraPath = "builtin:walk";  // the temple's, not cornell's
  EXPECT_THROW(studyMotionPaths(o), UsageError);
}

}  // namespace
}  // namespace raylab
