// What `raylab bench` keeps of its cells. results.jsonl gets one JSON line per finished cell, appended and
// fsynced as the cell ends, so a killed sweep keeps what it measured (and `--resume` continues from it);
// results.csv is made from the JSONL alone when the sweep ends: each line carries its CSV columns as the
// bench formatted them.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/bench/bench_measure.h"
#include "app/bench/bench_sweep.h"
#include "renderer/vk/vk_context.h"

namespace raylab {

// One results.jsonl line, one round of one cell: "cell" (its index in the plan), "round" (0-based), paths_per_frame (width x height x spp), device,
// git_revision, view, label, settings, scene, result, run_facts (measured once per run: the empty dispatch's
// cost), and "csv" (column name -> the CSV's text).
nlohmann::json benchRecord(size_t cellIndex, uint32_t round, const VulkanContext& ctx, const BenchCell& cell, const std::string& view,
                           const SceneFacts& scene, const CellResult& r, const RunFacts& run);

struct BenchRecords {
  std::vector<nlohmann::json> records;  // in file order
  size_t wholeBytes = 0;                // the file's prefix of whole lines: what a resume keeps
  bool droppedLastLine = false;         // the last line was cut off (no newline, or not JSON): a kill
};
// Reads results.jsonl (a missing file holds no records). A cut-off last line is dropped; any other line
// that is not a record throws std::runtime_error naming the file and line.
BenchRecords readBenchRecords(const std::string& path);

// The CSV's columns, in order.
std::vector<std::string> benchCsvColumns();
// results.csv: the header, then one row per cell in plan order, its rounds made one (cellSummaries in
// app/bench/bench_rounds.h: times are medians over the rounds, with their spread).
std::string benchCsv(const std::vector<nlohmann::json>& records);
// cells.jsonl: one line per cell in plan order, its rounds made one (cellSummaries); what the charts and
// the study's report read.
std::string cellsJsonl(const std::vector<nlohmann::json>& records);

// What a finished sweep (or a merge) writes from its records: DIR/results.csv, DIR/cells.jsonl and
// DIR/resolution.txt (app/bench/bench_resolution.h), each through writeFileChecked (throws WriteError); returns the
// resolution's text, which the bench prints.
std::string writeSweepSummaries(const std::string& dir, const std::vector<nlohmann::json>& records);
// Removes them: a sweep that starts or resumes has not ended.
void removeSweepSummaries(const std::string& dir);

}  // namespace raylab
