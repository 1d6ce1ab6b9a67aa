// The spread of repeated measurements: a cell's timed frames within one round, and a cell's per-round medians
// over the rounds of a sweep (app/bench/bench_rounds.h). Pure host code (the CPU tests check it).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace raylab {

// The median, extremes and quartiles (medians of the lower and upper halves, the median itself left out of
// both for an odd count) of some values; all 0 for none.
struct Spread {
  double median = 0.0, min = 0.0, max = 0.0, q1 = 0.0, q3 = 0.0;
};
Spread spreadOf(std::vector<double> values);

// Two spreads whose [min, max] overlap: the difference of their medians is within the noise their values
// show, and no report may call one of them faster ("not distinguishable here").
bool overlaps(const Spread& a, const Spread& b);

// {"median", "min", "max", "q1", "q3"}; with `measured` false (a spread of one value, which shows no noise)
// the last four are null: not measured, never a number.
nlohmann::json toJson(const Spread& s, bool measured = true);

// A CSV cell: the number as an ostream writes it (6 significant digits), or empty when not measured. Every
// bench output writes "not measured" one way: empty in the CSV, null in JSON, "n/a" on screen.
std::string csvNumber(std::optional<double> value);
// A CSV text cell: quoted, with its own double quotes turned into apostrophes (device and driver names).
std::string csvText(std::string text);
// A figure the renderer writes as a negative number when it did not measure it (renderer/frame_stats.h).
inline std::optional<double> measuredOrNone(double value) {
  return value < 0.0 ? std::nullopt : std::optional<double>(value);
}
// "12.3" for a measured value, "n/a" otherwise (progress lines, the summary text).
std::string screenNumber(std::optional<double> value, int decimals = 2);

}  // namespace raylab
