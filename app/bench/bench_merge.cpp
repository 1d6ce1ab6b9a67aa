#include "app/bench/bench_merge.h"

#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <stdexcept>

#include "app/bench/bench_charts_run.h"
#include "app/bench/bench_path_summary.h"
#include "app/bench/bench_results.h"
#include "app/bench/bench_resume.h"
#include "app/bench/bench_rounds.h"
#include "app/cli_options.h"
#include "app/scene_setup.h"
#include "renderer/checked_write.h"

namespace raylab {
namespace {

struct MergeRequest {
  std::vector<std::string> dirs;
  std::string outDir = "bench-out";
  bool charts = true;
};

MergeRequest parseMerge(const std::vector<std::string>& args) {
  MergeRequest r;
  for (size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--merge") {
      while (i + 1 < args.size() && args[i + 1].rfind("--", 0) != 0) r.dirs.push_back(args[++i]);
    } else if (args[i] == "--out-dir") {
      if (i + 1 >= args.size()) throw UsageError("--out-dir needs a folder");
      r.outDir = args[++i];
    } else if (args[i] == "--no-charts") {
      r.charts = false;
    } else {
      throw UsageError("--merge takes shard folders, --out-dir and --no-charts only, not '" + args[i] +
                       "' (the sweep is the one the folders recorded)");
    }
  }
  if (r.dirs.empty()) throw UsageError("--merge needs the shard folders of a sweep (e.g. --merge s0 s1 s2)");
  std::error_code ec;
  for (const std::string& d : r.dirs)
    if (std::filesystem::equivalent(d, r.outDir, ec))
      throw UsageError("--merge: --out-dir " + r.outDir + " is one of the shard folders; name a new folder");
  return r;
}

struct Shard {
  std::string dir;
  SweepRecord record;
  std::vector<nlohmann::json> records;
  std::vector<nlohmann::json> pathFrames;  // a --camera-path sweep's path_frames.jsonl
};

// The shards' records in plan order, or UsageError saying why these folders are not one whole sweep.
std::vector<nlohmann::json> mergedRecords(const std::vector<Shard>& shards) {
  const Shard& first = shards.front();
  const uint32_t count = first.record.shard.count;
  std::map<uint32_t, const Shard*> byIndex;
  for (const Shard& s : shards) {
    if (s.record.gitRevision != first.record.gitRevision)
      throw UsageError(s.dir + " was measured at revision " + s.record.gitRevision + " and " + first.dir + " at " +
                       first.record.gitRevision + ": shards of one sweep come from one build");
    if (s.record.definition.dump() != first.record.definition.dump())
      throw UsageError(s.dir + " holds a different sweep from " + first.dir + " (their sweep.json definitions differ)");
    if (s.record.shard.count != count)
      throw UsageError(s.dir + " is shard " + s.record.shard.text() + " and " + first.dir + " shard " +
                       first.record.shard.text() + ": shards of one split have one K");
    if (!byIndex.emplace(s.record.shard.index, &s).second)
      throw UsageError("shard " + s.record.shard.text() + " is given twice (" + byIndex[s.record.shard.index]->dir +
                       " and " + s.dir + ")");
  }
  for (uint32_t i = 0; i < count; ++i)
    if (!byIndex.count(i))
      throw UsageError("shard " + std::to_string(i) + "/" + std::to_string(count) + " is missing: merge all " +
                       std::to_string(count) + " shards of the sweep");
  const size_t cells = first.record.definition.at("cells").size();
  // Folders from before rounds have no "rounds": one round.
  const uint32_t rounds = first.record.definition.value("rounds", 1u);
  // Of a cell's round recorded twice (a resumed cell), the last record.
  std::map<std::pair<size_t, uint32_t>, nlohmann::json> byCell;
  for (const Shard& s : shards) {
    std::set<std::pair<size_t, uint32_t>> own;
    for (const nlohmann::json& r : s.records) {
      const size_t cell = r.at("cell").get<size_t>();
      if (cell >= cells || !s.record.shard.contains(cell) || roundOf(r) >= rounds)
        throw UsageError(s.dir + "/results.jsonl has cell " + std::to_string(cell) + " round " + std::to_string(roundOf(r)) +
                         ", which is not shard " + s.record.shard.text() + "'s (a damaged folder?)");
      own.insert({cell, roundOf(r)});
      byCell[{cell, roundOf(r)}] = r;
    }
    size_t expected = 0;
    std::string missing;  // the first few cell rounds the shard lacks, by cell number and label
    size_t missingCount = 0;
    for (size_t c = 0; c < cells; ++c) {
      if (!s.record.shard.contains(c)) continue;
      expected += rounds;
      for (uint32_t round = 0; round < rounds; ++round) {
        if (own.count({c, round})) continue;
        if (++missingCount <= 5)
          missing += std::string(missing.empty() ? "" : ", ") + "cell " + std::to_string(c) + " (" +
                     first.record.definition.at("cells").at(c).value("label", std::string("?")) + ") round " +
                     std::to_string(round);
      }
    }
    if (own.size() != expected)
      throw UsageError(s.dir + " (shard " + s.record.shard.text() + ") has " + std::to_string(own.size()) + " of its " +
                       std::to_string(expected) + " cell rounds; missing " + missing +
                       (missingCount > 5 ? " and " + std::to_string(missingCount - 5) + " more" : "") +
                       ": finish it first (raylab bench --resume " + s.dir + ")");
  }
  std::vector<nlohmann::json> out;
  for (auto& [cell, r] : byCell) out.push_back(std::move(r));
  return out;
}

}  // namespace

int runBenchMerge(const std::vector<std::string>& args) {
  MergeRequest request;
  std::vector<Shard> shards;
  std::vector<nlohmann::json> records;
  try {
    request = parseMerge(args);
    for (const std::string& dir : request.dirs) {
      Shard s{dir, readSweepRecord(dir), {}};
      try {
        s.records = readBenchRecords(dir + "/results.jsonl").records;
        s.pathFrames = readPathFrames(dir);
      } catch (const std::runtime_error& e) {
        throw UsageError(e.what());
      }
      shards.push_back(std::move(s));
    }
    records = mergedRecords(shards);
  } catch (const UsageError& e) {
    std::fprintf(stderr, "raylab bench: --merge: %s\n", e.what());
    return kExitUsage;
  }
  const std::string& out = request.outDir;
  std::string resolution;
  try {
    std::filesystem::create_directories(out);
    SweepRecord whole = shards.front().record;
    whole.shard = BenchShard{};
    writeSweepRecord(out, whole);
    std::string jsonl;
    for (const nlohmann::json& r : records) jsonl += r.dump() + "\n";
    writeFileChecked(out + "/results.jsonl", jsonl);
    resolution = writeSweepSummaries(out, records);
    // A camera-path sweep's frames, of the cell rounds kept, and its motion summaries from them.
    std::set<std::pair<size_t, uint32_t>> kept;
    for (const nlohmann::json& r : records) kept.insert({r.at("cell").get<size_t>(), roundOf(r)});
    std::vector<std::vector<nlohmann::json>> shardFrames;
    for (Shard& s : shards) shardFrames.push_back(std::move(s.pathFrames));
    const std::vector<nlohmann::json> frames = mergedPathFrames(shardFrames, kept);
    if (!frames.empty()) {
      std::string lines;
      for (const nlohmann::json& f : frames) lines += f.dump() + "\n";
      writeFileChecked(out + "/" + kPathFramesFile, lines);
      writePathSummaries(out);
    }
  } catch (const WriteError& e) {
    std::fprintf(stderr, "raylab bench: --merge: %s\n", e.what());
    return kExitFailure;
  } catch (const std::filesystem::filesystem_error& e) {
    std::fprintf(stderr, "raylab bench: --merge: %s\n", e.what());
    return kExitFailure;
  }
  std::printf("%sbench: merged %zu shards, %zu cells, into %s/results.csv and results.jsonl\n", resolution.c_str(), shards.size(),
              records.size(), out.c_str());
  std::fflush(stdout);
  return !request.charts || drawAndReportCharts(out) ? kExitOk : kExitFailure;
}

}  // namespace raylab
