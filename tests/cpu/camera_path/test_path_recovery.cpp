// Recovery after a cut (app/camera_path/path_recovery.h) on synthetic series, and the bench's path summary
// (app/bench/bench_path_summary.h) made from synthetic path frames: frames until the prediction error is back
// within 10% of its value before the cut, "never" where it is not back before the next cut or the end
// (reported as such, not as 0), and nothing to recover for a strategy that predicts nothing.
#include <gtest/gtest.h>

#include <optional>
#include <set>
#include <vector>

#include "app/bench/bench_path_summary.h"
#include "app/camera_path/path_recovery.h"

namespace raylab {
namespace {

using Series = std::vector<std::optional<double>>;

// A series of `n` frames: `before` until `cut`, then a jump to `peak` decaying geometrically by `decay` a
// frame towards `settle`. Returns the first frame at or after the cut within tolerance of `before`, by brute
// force, for the test's own expectation.
struct Decay {
  Series error;
  std::vector<bool> cut;
};
Decay decaying(size_t n, size_t cutAt, double before, double peak, double settle, double decay) {
  Decay d{Series(n), std::vector<bool>(n, false)};
  double excess = peak - settle;
  for (size_t f = 0; f < n; ++f) {
    if (f < cutAt) {
      d.error[f] = before;
      continue;
    }
    d.error[f] = settle + excess;
    excess *= decay;
  }
  d.cut[cutAt] = true;
  return d;
}

std::optional<uint32_t> expectedFrames(const Decay& d, size_t cutAt, double before, double tolerance) {
  for (size_t f = cutAt; f < d.error.size(); ++f)
    if (*d.error[f] <= before * (1.0 + tolerance)) return uint32_t(f - cutAt);
  return std::nullopt;
}

TEST(PathRecovery, DecayingErrorRecoversWhenWithinTolerance) {
  for (double decay : {0.3, 0.5, 0.8}) {
    const Decay d = decaying(40, 10, 0.1, 0.5, 0.1, decay);
    const std::vector<CutRecovery> r = recoveryAfterCuts(d.error, d.cut);
    ASSERT_EQ(r.size(), 1u);
    EXPECT_EQ(r[0].cutFrame, 10u);
    ASSERT_TRUE(r[0].before);
    EXPECT_DOUBLE_EQ(*r[0].before, 0.1);
    EXPECT_EQ(r[0].frames, expectedFrames(d, 10, 0.1, kRecoveryTolerance)) << decay;
    ASSERT_TRUE(r[0].frames);
    EXPECT_GT(*r[0].frames, 0u);
    EXPECT_EQ(r[0].framesSeen, 30u);
  }
  // Faster decay recovers sooner.
  const Decay fast = decaying(40, 10, 0.1, 0.5, 0.1, 0.3), slow = decaying(40, 10, 0.1, 0.5, 0.1, 0.8);
  EXPECT_LT(*recoveryAfterCuts(fast.error, fast.cut)[0].frames, *recoveryAfterCuts(slow.error, slow.cut)[0].frames);
}

TEST(PathRecovery, ErrorThatSettlesHigherNeverRecovers) {
  // Settles 50% above the error before the cut: never within 10%, reported as never, not 0.
  const Decay d = decaying(30, 5, 0.2, 0.6, 0.3, 0.5);
  const std::vector<CutRecovery> r = recoveryAfterCuts(d.error, d.cut);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_FALSE(r[0].frames.has_value());
  EXPECT_EQ(r[0].framesSeen, 25u);
  EXPECT_FALSE(toJson(r[0])["recovered"].get<bool>());
  EXPECT_TRUE(toJson(r[0])["frames"].is_null());
}

// The segment's own level: an error that settles 50% above the level before the cut never returns "before",
// but it settles, and the frames to its settled level (the median of the segment's second half) are those of
// the decay; a faster decay settles sooner. Frames without a value are skipped.
TEST(PathRecovery, ErrorSettlesAtTheNewViewsOwnLevel) {
  for (double decay : {0.3, 0.6}) {
    Decay d = decaying(30, 5, 0.2, 0.9, 0.3, decay);
    d.error[29] = std::nullopt;
    const std::vector<CutRecovery> r = recoveryAfterCuts(d.error, d.cut);
    ASSERT_EQ(r.size(), 1u);
    EXPECT_FALSE(r[0].frames.has_value());
    ASSERT_TRUE(r[0].settled);
    // The second half of the segment (frames 17..28 measured): within a hair of the settle level.
    EXPECT_NEAR(*r[0].settled, 0.3, 0.3 * 0.01);
    ASSERT_TRUE(r[0].framesToSettle);
    EXPECT_EQ(r[0].framesToSettle, expectedFrames(d, 5, *r[0].settled, kRecoveryTolerance)) << decay;
    EXPECT_GT(*r[0].framesToSettle, 0u);
    EXPECT_EQ(toJson(r[0])["frames_to_settle"].get<uint32_t>(), *r[0].framesToSettle);
  }
  const Decay fast = decaying(30, 5, 0.2, 0.9, 0.3, 0.3), slow = decaying(30, 5, 0.2, 0.9, 0.3, 0.6);
  EXPECT_LT(*recoveryAfterCuts(fast.error, fast.cut)[0].framesToSettle,
            *recoveryAfterCuts(slow.error, slow.cut)[0].framesToSettle);
  // Nothing measured after the cut: no settled level, no frames.
  Decay blank = decaying(20, 5, 0.2, 0.9, 0.3, 0.5);
  for (size_t f = 5; f < 20; ++f) blank.error[f] = std::nullopt;
  const CutRecovery none = recoveryAfterCuts(blank.error, blank.cut)[0];
  EXPECT_FALSE(none.settled.has_value());
  EXPECT_FALSE(none.framesToSettle.has_value());
  EXPECT_TRUE(toJson(none)["settled"].is_null());
}

TEST(PathRecovery, NoJumpIsZeroFramesAndLowerErrorCounts) {
  Decay d = decaying(12, 4, 0.2, 0.2, 0.2, 0.5);
  EXPECT_EQ(recoveryAfterCuts(d.error, d.cut)[0].frames, std::optional<uint32_t>(0));
  d = decaying(12, 4, 0.2, 0.1, 0.1, 0.5);  // better after the cut
  EXPECT_EQ(recoveryAfterCuts(d.error, d.cut)[0].frames, std::optional<uint32_t>(0));
}

TEST(PathRecovery, EachCutSearchesUntilTheNextAndSkipsUnmeasuredFrames) {
  // Two cuts; the first never recovers before the second; frames without a value are skipped.
  Series e{0.1, 0.1, 0.5, 0.4, std::nullopt, 0.3, 0.1, std::nullopt, 0.5, 0.105};
  std::vector<bool> cut(e.size(), false);
  cut[2] = cut[6] = true;
  const std::vector<CutRecovery> r = recoveryAfterCuts(e, cut);
  ASSERT_EQ(r.size(), 2u);
  EXPECT_FALSE(r[0].frames.has_value());
  EXPECT_EQ(r[0].framesSeen, 4u);
  EXPECT_DOUBLE_EQ(*r[1].before, 0.3);  // the last measured value before the second cut
  EXPECT_EQ(r[1].frames, std::optional<uint32_t>(0));  // 0.1 <= 0.3 * 1.1
  // The tolerance is a parameter: with none, 0.105 is not back within 0.1's.
  Series f{0.1, 0.1, 0.5, 0.2, 0.105};
  std::vector<bool> c2(f.size(), false);
  c2[2] = true;
  EXPECT_EQ(recoveryAfterCuts(f, c2, 0.10)[0].frames, std::optional<uint32_t>(2));
  EXPECT_FALSE(recoveryAfterCuts(f, c2, 0.0)[0].frames.has_value());
}

TEST(PathRecovery, NothingBeforeTheCutHasNoBaseline) {
  Series e{std::nullopt, std::nullopt, 0.3, 0.2};
  std::vector<bool> cut{false, false, true, false};
  const std::vector<CutRecovery> r = recoveryAfterCuts(e, cut);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_FALSE(r[0].before.has_value());
  EXPECT_FALSE(r[0].frames.has_value());
  // A cut flag on frame 0 is no cut from anything.
  EXPECT_TRUE(recoveryAfterCuts(Series{0.1, 0.2}, {true, false}).empty());
}

nlohmann::json frame(size_t cell, uint32_t round, uint32_t f, double workMs, std::optional<double> error, bool cut,
                     bool detailed) {
  return {{"cell", cell},         {"round", round},   {"path_frame", f}, {"label", "cell" + std::to_string(cell)},
          {"scene", "s"},         {"camera_path", "p"}, {"work_ms", workMs}, {"cut", cut}, {"detailed", detailed},
          {"prediction_error_mean", error ? nlohmann::json(*error) : nlohmann::json(nullptr)}};
}

TEST(PathSummary, MediansOverRoundsAndRecoveryFromTheDetailedReplay) {
  const Decay d = decaying(12, 6, 0.1, 0.4, 0.1, 0.5);
  std::vector<nlohmann::json> frames;
  for (uint32_t round = 0; round < 3; ++round)
    for (uint32_t f = 0; f < 12; ++f) {
      frames.push_back(frame(0, round, f, 1.0 + round, round == 0 ? d.error[f] : std::nullopt, d.cut[f], round == 0));
      frames.push_back(frame(1, round, f, 2.0, std::nullopt, d.cut[f], round == 0));  // predicts nothing
    }
  const nlohmann::json s = pathSummary(frames);
  ASSERT_EQ(s["cells"].size(), 2u);
  const nlohmann::json& learned = s["cells"][0];
  EXPECT_EQ(learned["frames"], 12);
  EXPECT_EQ(learned["rounds"], 3);
  EXPECT_DOUBLE_EQ(learned["frame_ms"][0].get<double>(), 2.0);  // the median of 1, 2, 3
  EXPECT_DOUBLE_EQ(learned["total_ms"].get<double>(), 24.0);
  // The rounds' totals are 12, 24 and 36 ms: their spread, and the markdown's range.
  EXPECT_DOUBLE_EQ(learned["total_ms_spread"]["min"].get<double>(), 12.0);
  EXPECT_DOUBLE_EQ(learned["total_ms_spread"]["max"].get<double>(), 36.0);
  EXPECT_DOUBLE_EQ(learned["total_ms_spread"]["median"].get<double>(), 24.0);
  EXPECT_TRUE(pathSummary({frames.front()})["cells"][0]["total_ms_spread"]["min"].is_null());  // one round
  EXPECT_EQ(learned["cuts"], nlohmann::json::array({6}));
  ASSERT_EQ(learned["recovery"].size(), 1u);
  const std::optional<uint32_t> want = expectedFrames(d, 6, 0.1, kRecoveryTolerance);
  EXPECT_EQ(learned["recovery"][0]["frames"], want ? nlohmann::json(*want) : nlohmann::json(nullptr));
  EXPECT_TRUE(s["cells"][1]["recovery"].empty());
  EXPECT_TRUE(s["cells"][1]["mean_prediction_error"].is_null());
  const std::string md = pathSummaryMarkdown(s);
  EXPECT_NE(md.find("| cell1 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| 24.0 (12.0-36.0) |"), std::string::npos) << md;
  EXPECT_NE(md.find("no prediction"), std::string::npos) << md;
  EXPECT_NE(md.find("cut@6: " + std::to_string(*want)), std::string::npos) << md;
}

// bench --merge's path frames: two shards (cells 0 and 2, cell 1), given in any order and each written
// cell-major as a shard writes them; only the kept cell rounds stay (a shard's round the merge did not keep, as a
// cut-short one, goes), a frame written twice keeps its last line, and the result is ordered by cell, round and
// path frame, so that its summary equals the one of the same frames written by an unsharded run.
TEST(PathSummary, MergedShardsKeepTheKeptRoundsInOrder) {
  std::vector<nlohmann::json> whole, shardA, shardB;
  for (size_t cell : {0u, 1u, 2u})
    for (uint32_t round = 0; round < 2; ++round)
      for (uint32_t f = 0; f < 4; ++f) {
        const nlohmann::json x = frame(cell, round, f, 1.0 + cell + 0.1 * f + round, std::nullopt, f == 2, round == 0);
        whole.push_back(x);
        (cell == 1 ? shardB : shardA).push_back(x);
      }
  // Shard B also holds a third round of cell 1 the merge does not keep, and writes its frame 3 again.
  shardB.push_back(frame(1, 2, 0, 99.0, std::nullopt, false, false));
  nlohmann::json again = shardB[7];
  again["work_ms"] = 7.5;
  shardB.push_back(again);
  std::set<std::pair<size_t, uint32_t>> kept;
  for (size_t cell : {0u, 1u, 2u})
    for (uint32_t round = 0; round < 2; ++round) kept.insert({cell, round});

  const std::vector<nlohmann::json> merged = mergedPathFrames({shardB, shardA}, kept);
  ASSERT_EQ(merged.size(), whole.size());
  for (size_t i = 0; i < merged.size(); ++i) {
    EXPECT_EQ(merged[i]["cell"], whole[i]["cell"]) << i;
    EXPECT_EQ(merged[i]["round"], whole[i]["round"]) << i;
    EXPECT_EQ(merged[i]["path_frame"], whole[i]["path_frame"]) << i;
  }
  EXPECT_EQ(merged[15]["work_ms"], 7.5);  // cell 1, round 1, frame 3: its last line
  EXPECT_EQ(pathSummary(merged)["cells"][0], pathSummary(whole)["cells"][0]);
  EXPECT_EQ(pathSummary(merged)["cells"][2], pathSummary(whole)["cells"][2]);
  EXPECT_TRUE(mergedPathFrames({shardA, shardB}, {}).empty());  // nothing kept, nothing merged
}

}  // namespace
}  // namespace raylab
