#include "app/bench/bench_resume.h"

#include <fstream>

#include "renderer/checked_write.h"
#include "renderer/git_revision.h"
#include "renderer/stats_json.h"

namespace raylab {
namespace {

std::string sweepPath(const std::string& dir) { return dir + "/sweep.json"; }

// Compared as text: JSON has no infinity (an unbounded Gaussian reset is null on both sides once read
// back), and a float prints the same digits again after a round trip.
bool same(const nlohmann::json& a, const nlohmann::json& b) { return a.dump() == b.dump(); }

}  // namespace

nlohmann::json sweepDefinition(const BenchPlan& plan) {
  nlohmann::json cases = nlohmann::json::array(), cells = nlohmann::json::array();
  for (const BenchCase& c : plan.cases) cases.push_back({{"scene", c.scene}, {"view", c.view}});
  for (const BenchCell& c : plan.cells)
    cells.push_back({{"case", c.caseIndex}, {"label", c.label}, {"settings", toJson(c.settings)}});
  return {{"cases", cases},
          {"cells", cells},
          {"timed_frames", plan.timedFrames},
          {"warmup_frames", plan.warmupFrames},
          {"reference_spp", plan.referenceSpp},
          {"rounds", plan.rounds},
          {"detail_frame", plan.detailFrame}};
}

void writeSweepRecord(const std::string& dir, const SweepRecord& r) {
  const nlohmann::json record = {
      {"git_revision", r.gitRevision}, {"args", r.args}, {"shard", r.shard.text()}, {"definition", r.definition}};
  writeFileChecked(sweepPath(dir), record.dump(1) + "\n");
}

void writeSweepRecord(const std::string& dir, const BenchPlan& plan, const std::vector<std::string>& args,
                      const BenchShard& shard) {
  writeSweepRecord(dir, SweepRecord{gitRevision(), args, sweepDefinition(plan), shard});
}

SweepRecord readSweepRecord(const std::string& dir) {
  std::ifstream in(sweepPath(dir));
  if (!in) throw UsageError(dir + ": no sweep.json there (not a raylab bench folder)");
  try {
    const nlohmann::json j = nlohmann::json::parse(in);
    // Folders from before --shard have no "shard": they hold the whole sweep.
    const BenchShard shard = j.contains("shard") ? parseShard(j.at("shard").get<std::string>()) : BenchShard{};
    return {j.at("git_revision").get<std::string>(), j.at("args").get<std::vector<std::string>>(), j.at("definition"),
            shard};
  } catch (const UsageError& e) {
    throw UsageError(dir + ": sweep.json is damaged (" + e.what() + ")");
  } catch (const nlohmann::json::exception& e) {
    throw UsageError(dir + ": sweep.json is damaged (" + e.what() + ")");
  }
}

std::string resumeRefusal(const SweepRecord& recorded, const BenchPlan& plan) {
  if (recorded.gitRevision != gitRevision())
    return "it was measured at revision " + recorded.gitRevision + " and this raylab is " + gitRevision() +
           ": finish it with that build, or start a new folder";
  const nlohmann::json now = sweepDefinition(plan);
  const nlohmann::json& was = recorded.definition;
  if (same(was, now)) return "";
  const std::string differs = "a different sweep from the one recorded in its sweep.json: ";
  if (!was.contains("cells") || was["cells"].size() != now["cells"].size())
    return differs + std::to_string(was.value("cells", nlohmann::json::array()).size()) + " cells there, " +
           std::to_string(now["cells"].size()) + " here";
  for (size_t i = 0; i < now["cells"].size(); ++i) {
    const nlohmann::json &a = was["cells"][i], &b = now["cells"][i];
    if (same(a, b)) continue;
    const std::string there = a.value("label", ""), here = b.value("label", "");
    return differs + "cell " + std::to_string(i + 1) + " is '" + there + "' there and '" + here + "' here" +
           (there == here ? " with other settings" : "");
  }
  for (const char* key : {"timed_frames", "warmup_frames", "reference_spp", "rounds", "detail_frame", "cases"})
    if (!was.contains(key) || !same(was[key], now[key]))
      return differs + key + " is " + (was.contains(key) ? was[key].dump() : "missing") + " there and " + now[key].dump() + " here";
  return differs + "its definition differs";
}

}  // namespace raylab
