// Rounds (issue 34): a bench sweep measures every cell once per round, and each round in another order, so
// that a drift of the device (clocks, heat, another process) falls on every cell alike instead of on the
// cells that happened to run late. One run of a cell told little: three identical lavapipe sweeps read the
// unsorted wavefront at 25.55, 24.24 and 14.48 ms. results.jsonl keeps one record per cell and round; the
// cell's figures are the median over its rounds of each round's median, with the spread over the rounds.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <nlohmann/json.hpp>

namespace raylab {

inline constexpr uint32_t kDefaultRounds = 3;
inline constexpr uint32_t kMaxRounds = 100;

// The order of `count` cells (0 .. count-1, positions in a case's list) in round `round`: round 0 in plan
// order, every later one a permutation drawn from the round number alone (the same on every machine and
// every run, so a resumed sweep runs the cells it lacks in the order the whole one would have).
std::vector<size_t> roundOrder(size_t count, uint32_t round);

// A record's round (records from before rounds have none: round 0).
uint32_t roundOf(const nlohmann::json& record);

// One record per cell, in plan order, made of its rounds' records (of a cell and round recorded twice, the
// last): the first round's record (settings, scene, counting frame, image error: what is not a time) with
//   "rounds": how many rounds it has,
//   "result": every time (frame_ms, wall_ms, trace_after_first_ms, stage_ms, stage_bounce_ms, rays_per_second,
//             error_curve_ms) the median over the rounds of each round's median; frame_ms, wall_ms,
//             trace_after_first_ms and each stage_ms the spread over the rounds ({median, min, max, q1, q3};
//             min to q3 null with one round: no spread measured) and "round_frame_ms" each round's median,
//   "csv":    the same for the CSV's times (frame_ms_median, _min, _max, _q1, _q3, rounds,
//             trace_after_first_ms, _min, _max, every stage's column, rays_per_second); empty: not measured.
std::vector<nlohmann::json> cellSummaries(const std::vector<nlohmann::json>& records);

}  // namespace raylab
