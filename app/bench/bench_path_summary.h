// What `raylab bench --camera-path` keeps of its path frames (issue 37): path_frames.jsonl, one line per
// path frame of every cell and round (app/bench/bench_path.h's figures, with "cell", "round", "label", "scene",
// "strategy", "sort_policy" and "camera_path"), appended and fsynced with the cell's results.jsonl record;
// and when the sweep ends, motion.json and motion.md: per cell the path's time, its mean prediction error
// and the recovery after each cut (app/camera_path/path_recovery.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace raylab {

inline constexpr const char* kPathFramesFile = "path_frames.jsonl";

// The lines of DIR/path_frames.jsonl (none: no file); a cut-off last line (a kill) is dropped, any other
// line that is not a path frame throws std::runtime_error naming the file and line.
std::vector<nlohmann::json> readPathFrames(const std::string& dir);

// A resumed sweep keeps the path frames of the cell rounds it keeps (`finished`: (cell, round)) and drops
// those of a round a kill cut short, which runs again (writeFileChecked; throws WriteError).
void keepFinishedPathFrames(const std::string& dir, const std::set<std::pair<size_t, uint32_t>>& finished);

// The path frames of a sweep merged from its shards (`bench --merge`): of every shard's frames (`shards`, each
// as readPathFrames gives them), those of the cell rounds the merge keeps (`kept`: (cell, round)), ordered by
// cell, round and path frame; a frame recorded twice (a round resumed within its shard) keeps its last line.
std::vector<nlohmann::json> mergedPathFrames(const std::vector<std::vector<nlohmann::json>>& shards,
                                             const std::set<std::pair<size_t, uint32_t>>& kept);

// Per cell, in cell order: "cell", "label", "scene", "strategy", "sort_policy", "camera_path", "frames",
// "rounds", "frame_ms" (per path frame: the median over the rounds of its work time), "mean_frame_ms",
// "total_ms" (the median over the rounds of the path's total), "total_ms_spread" (those totals' spread,
// app/bench/bench_spread.h's JSON: min, max and quartiles null for one round), "prediction_error" (per path
// frame, from the detailed replay; null where not measured), "mean_prediction_error" (null: none measured), "cuts" (the
// cut frames) and "recovery" (one per cut, app/camera_path/path_recovery.h; empty without a detailed replay).
nlohmann::json pathSummary(const std::vector<nlohmann::json>& frames);
// The summary as markdown: one table per camera path and scene, a row per cell.
std::string pathSummaryMarkdown(const nlohmann::json& summary);

// Writes DIR/motion.json and DIR/motion.md from DIR/path_frames.jsonl (nothing when it holds no frames);
// returns whether it wrote them. Throws WriteError.
bool writePathSummaries(const std::string& dir);
void removePathSummaries(const std::string& dir);

}  // namespace raylab
