// A bench output folder records the sweep that made it in sweep.json (the plan: cases, cells with their
// settings, frame counts; the arguments; the git revision), written before the first cell, so that
// `raylab bench ... --resume DIR` can continue a killed sweep: only the cells not yet in DIR/results.jsonl
// run, and only when the sweep and the build are the ones DIR records (results of two sweeps or two
// builds never mix in one folder).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/bench/bench_shard.h"
#include "app/bench/bench_sweep.h"

namespace raylab {

// What defines a sweep's results: two plans with the same definition measure the same cells the same way.
nlohmann::json sweepDefinition(const BenchPlan& plan);

struct SweepRecord {
  std::string gitRevision;
  std::vector<std::string> args;  // the bench's arguments, without --out-dir, --resume and --shard
  nlohmann::json definition;
  BenchShard shard;               // which cells of the definition the folder runs (0/1: all)
};

// Writes DIR/sweep.json through writeFileChecked (throws WriteError).
void writeSweepRecord(const std::string& dir, const BenchPlan& plan, const std::vector<std::string>& args,
                      const BenchShard& shard = {});
void writeSweepRecord(const std::string& dir, const SweepRecord& record);
// Reads DIR/sweep.json; throws UsageError when it is missing or unreadable (not a bench folder).
SweepRecord readSweepRecord(const std::string& dir);

// Empty when `plan`, at this build, continues the recorded sweep; else what differs.
std::string resumeRefusal(const SweepRecord& recorded, const BenchPlan& plan);

}  // namespace raylab
