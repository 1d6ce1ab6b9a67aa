// Rounds and spreads of `raylab bench` (issue 34): the order of each round, the spread over rounds, a cell's
// rounds made one (medians, spread, empty for not measured), the resolution text that says which differences
// the spread cannot resolve, and --rounds in the plan and in what a resume compares. Records are made here
// by hand: nothing depends on a device or on timing.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "app/bench/bench_resolution.h"
#include "app/bench/bench_results.h"
#include "app/bench/bench_resume.h"
#include "app/bench/bench_rounds.h"
#include "app/bench/bench_spread.h"
#include "app/bench/bench_sweep.h"
#include "renderer/git_revision.h"

namespace raylab {
namespace {

TEST(BenchRounds, EachRoundIsAPermutationInItsOwnOrder) {
  EXPECT_EQ(roundOrder(5, 0), (std::vector<size_t>{0, 1, 2, 3, 4}));  // the first round in plan order
  std::set<std::vector<size_t>> orders;
  for (uint32_t round = 0; round < 4; ++round) {
    std::vector<size_t> order = roundOrder(8, round);
    EXPECT_EQ(order, roundOrder(8, round)) << "round " << round << " is not deterministic";
    std::vector<size_t> sorted = order;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(sorted, roundOrder(8, 0)) << "round " << round << " is not a permutation";
    orders.insert(order);
  }
  EXPECT_EQ(orders.size(), 4u) << "two rounds ran the cells in one order";
  EXPECT_TRUE(roundOrder(0, 3).empty());
  EXPECT_EQ(roundOrder(1, 3), (std::vector<size_t>{0}));
}

TEST(BenchRounds, SpreadHasQuartilesAndOverlapIsInclusive) {
  const Spread s = spreadOf({4.0, 1.0, 3.0, 2.0});
  EXPECT_DOUBLE_EQ(s.median, 2.5);
  EXPECT_DOUBLE_EQ(s.min, 1.0);
  EXPECT_DOUBLE_EQ(s.max, 4.0);
  EXPECT_DOUBLE_EQ(s.q1, 1.5);
  EXPECT_DOUBLE_EQ(s.q3, 3.5);
  const Spread odd = spreadOf({5.0, 1.0, 3.0, 2.0, 4.0});
  EXPECT_DOUBLE_EQ(odd.median, 3.0);
  EXPECT_DOUBLE_EQ(odd.q1, 1.5);  // {1, 2}: the median left out of both halves
  EXPECT_DOUBLE_EQ(odd.q3, 4.5);
  EXPECT_TRUE(overlaps(spreadOf({1.0, 2.0}), spreadOf({2.0, 3.0})));
  EXPECT_FALSE(overlaps(spreadOf({1.0, 2.0}), spreadOf({2.5, 3.0})));
  EXPECT_FALSE(overlaps(spreadOf({2.5, 3.0}), spreadOf({1.0, 2.0})));
}

TEST(BenchRounds, NotMeasuredIsEmptyOrNull) {
  EXPECT_EQ(csvNumber(std::nullopt), "");
  EXPECT_EQ(csvNumber(0.0), "0");
  EXPECT_EQ(csvNumber(measuredOrNone(-1.0)), "");
  EXPECT_EQ(screenNumber(std::nullopt), "n/a");
  EXPECT_EQ(screenNumber(1.234), "1.23");
  const nlohmann::json one = toJson(spreadOf({2.0}), /*measured=*/false);
  EXPECT_DOUBLE_EQ(one["median"].get<double>(), 2.0);
  EXPECT_TRUE(one["min"].is_null());
  EXPECT_TRUE(one["q3"].is_null());
}

// One round's record of a cell as the bench writes it (the parts the summary reads).
nlohmann::json roundRecord(size_t cell, uint32_t round, const std::string& label, double frameMs,
                           std::optional<double> traceLater, double traceMs) {
  nlohmann::json result = {
      {"frame_ms", {{"median", frameMs}, {"min", frameMs - 1}, {"max", frameMs + 1}}},
      {"wall_ms", {{"median", frameMs + 2}, {"min", frameMs}, {"max", frameMs + 3}}},
      {"trace_after_first_ms", traceLater ? nlohmann::json{{"median", *traceLater}} : nlohmann::json(nullptr)},
      {"stage_ms", {{"trace", {{"median", traceMs}}}}},
      {"stage_bounce_ms", {{"trace@0", traceMs}}},
      {"rays_per_second", 1e6},
      {"error_curve_ms", {frameMs, 2 * frameMs}},
      {"final_rel_mse", 0.5}};
  nlohmann::json csv = {{"scene", "\"temple\""}, {"view", "hall"}, {"width", "128"}, {"height", "64"},
                        {"spp_per_frame", "1"}, {"bounces", "2"}, {"label", "\"" + label + "\""},
                        {"frame_ms_median", std::to_string(frameMs)}, {"final_rel_mse", "0.5"},
                        {"trace_after_first_ms", ""}, {"shade_ms", ""}};
  return {{"cell", cell}, {"round", round}, {"label", label}, {"result", result}, {"csv", csv}};
}

TEST(BenchRounds, CellsAreMediansOverRoundsWithTheirSpread) {
  // Rounds recorded out of order, and round 1 of cell 0 twice (a resumed round): the last record counts.
  const std::vector<nlohmann::json> records = {
      roundRecord(0, 2, "none", 20.0, 8.0, 9.0), roundRecord(1, 0, "megakernel", 30.0, std::nullopt, 0.0),
      roundRecord(0, 0, "none", 10.0, 6.0, 7.0), roundRecord(0, 1, "none", 99.0, 7.0, 8.0),
      roundRecord(0, 1, "none", 30.0, 7.0, 8.0)};
  const std::vector<nlohmann::json> cells = cellSummaries(records);
  ASSERT_EQ(cells.size(), 2u);
  const nlohmann::json& none = cells[0];
  EXPECT_EQ(none["cell"], 0);
  EXPECT_FALSE(none.contains("round"));
  EXPECT_EQ(none["rounds"], 3);
  EXPECT_DOUBLE_EQ(none["result"]["frame_ms"]["median"].get<double>(), 20.0);
  EXPECT_DOUBLE_EQ(none["result"]["frame_ms"]["min"].get<double>(), 10.0);
  EXPECT_DOUBLE_EQ(none["result"]["frame_ms"]["max"].get<double>(), 30.0);
  EXPECT_EQ(none["result"]["round_frame_ms"], (nlohmann::json{10.0, 30.0, 20.0}));  // in round order
  EXPECT_DOUBLE_EQ(none["result"]["trace_after_first_ms"]["median"].get<double>(), 7.0);
  EXPECT_DOUBLE_EQ(none["result"]["stage_ms"]["trace"]["median"].get<double>(), 8.0);
  EXPECT_DOUBLE_EQ(none["result"]["error_curve_ms"][1].get<double>(), 40.0);  // 2 frames of the median
  EXPECT_EQ(none["csv"]["frame_ms_median"], "20");
  EXPECT_EQ(none["csv"]["frame_ms_min"], "10");
  EXPECT_EQ(none["csv"]["frame_ms_max"], "30");
  EXPECT_EQ(none["csv"]["trace_after_first_ms"], "7");
  EXPECT_EQ(none["csv"]["trace_after_first_ms_min"], "6");
  // One round: a median, and no spread (not measured), never a min equal to the max.
  const nlohmann::json& mega = cells[1];
  EXPECT_EQ(mega["rounds"], 1);
  EXPECT_TRUE(mega["result"]["frame_ms"]["min"].is_null());
  EXPECT_EQ(mega["csv"]["frame_ms_min"], "");
  EXPECT_EQ(mega["csv"]["frame_ms_max"], "");
  EXPECT_TRUE(mega["result"]["trace_after_first_ms"].is_null());
  EXPECT_EQ(mega["csv"]["trace_after_first_ms"], "");
}

// The CSV's cells of what was not measured are empty: never 0 or -1 (the megakernel's trace of bounces >= 1).
TEST(BenchRounds, CsvLeavesNotMeasuredEmpty) {
  const std::string csv = benchCsv({roundRecord(0, 0, "megakernel", 30.0, std::nullopt, 0.0),
                                    roundRecord(0, 1, "megakernel", 31.0, std::nullopt, 0.0)});
  std::istringstream in(csv);
  std::string header, row;
  std::getline(in, header);
  std::getline(in, row);
  auto split = [](const std::string& line) {
    std::vector<std::string> out;
    std::stringstream ss(line);
    for (std::string item; std::getline(ss, item, ',');) out.push_back(item);
    if (!line.empty() && line.back() == ',') out.push_back("");
    return out;
  };
  const std::vector<std::string> columns = split(header), values = split(row);
  ASSERT_EQ(columns.size(), values.size());
  auto at = [&](const std::string& c) {
    return values[size_t(std::find(columns.begin(), columns.end(), c) - columns.begin())];
  };
  EXPECT_EQ(at("trace_after_first_ms"), "");
  EXPECT_EQ(at("trace_after_first_ms_max"), "");
  EXPECT_EQ(at("shade_ms"), "");
  EXPECT_EQ(at("rounds"), "2");
  EXPECT_EQ(at("frame_ms_median"), "30.5");
  for (const std::string& v : values) EXPECT_NE(v, "-1");
}

TEST(BenchRounds, ResolutionNamesWhatTheSpreadCannotTellApart) {
  std::vector<nlohmann::json> records;
  const double none[] = {14.48, 25.55, 24.24}, fixed[] = {17.41, 28.48, 17.55}, mega[] = {40.0, 41.0, 42.0};
  for (uint32_t round = 0; round < 3; ++round) {
    records.push_back(roundRecord(0, round, "none", none[round], 5.0, 6.0));
    records.push_back(roundRecord(1, round, "fixed/radix", fixed[round], 5.0, 6.0));
    records.push_back(roundRecord(2, round, "megakernel", mega[round], std::nullopt, 0.0));
  }
  const std::string text = resolutionText(cellSummaries(records));
  EXPECT_NE(text.find("temple@hall 128x64 spp 1, 2 bounces, 3 rounds: fastest fixed/radix 17.55 ms [17.41-28.48]"),
            std::string::npos) << text;
  EXPECT_NE(text.find("not distinguishable from it here (spreads over the rounds overlap):\n    none 24.24 ms"),
            std::string::npos) << text;
  EXPECT_NE(text.find("slower beyond the spread:\n    megakernel 41.00 ms [40.00-42.00]"), std::string::npos) << text;

  const std::string once = resolutionText(cellSummaries({roundRecord(0, 0, "none", 10.0, 5.0, 6.0),
                                                         roundRecord(1, 0, "fixed/radix", 30.0, 5.0, 6.0)}));
  EXPECT_NE(once.find("one round shows no spread: no difference is resolved"), std::string::npos) << once;
  EXPECT_EQ(once.find("slower beyond"), std::string::npos) << once;
}

TEST(BenchRounds, RoundsFlagAndResume) {
  const std::vector<std::string> sweep = {"--cases", "cornell@front", "--strategies", "fixed"};
  EXPECT_EQ(parseBenchPlan(sweep).rounds, kDefaultRounds);
  std::vector<std::string> five = sweep;
  five.insert(five.end(), {"--rounds", "5"});
  EXPECT_EQ(parseBenchPlan(five).rounds, 5u);
  for (const char* bad : {"0", "101", "x", "-1"}) {
    std::vector<std::string> args = sweep;
    args.insert(args.end(), {"--rounds", bad});
    EXPECT_THROW(parseBenchPlan(args), UsageError) << bad;
  }
  // A resume with another round count is another sweep.
  const SweepRecord recorded{gitRevision(), sweep, sweepDefinition(parseBenchPlan(sweep)), {}};
  EXPECT_EQ(resumeRefusal(recorded, parseBenchPlan(sweep)), "");
  const std::string why = resumeRefusal(recorded, parseBenchPlan(five));
  EXPECT_NE(why.find("rounds is 3 there and 5 here"), std::string::npos) << why;
}

}  // namespace
}  // namespace raylab
