#include "app/bench/bench_path_summary.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <stdexcept>
#include <tuple>

#include "app/bench/bench_spread.h"
#include "app/camera_path/path_recovery.h"
#include "renderer/checked_write.h"

namespace raylab {
namespace {

std::string fileOf(const std::string& dir) { return dir + "/" + kPathFramesFile; }

std::optional<double> numberOr(const nlohmann::json& j, const char* key) {
  auto it = j.find(key);
  return it != j.end() && it->is_number() ? std::optional(it->get<double>()) : std::nullopt;
}

std::string fixed(double v, int digits) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", digits, v);
  return text;
}

std::string recoveryText(const nlohmann::json& r) {
  const std::string at = "cut@" + std::to_string(r.at("cut_frame").get<uint32_t>()) + ": ";
  if (r.at("before").is_null()) return at + "no error before it";
  // The frames to the segment's own settled level, where it has one (path_recovery.h says why both).
  const nlohmann::json settle = r.value("frames_to_settle", nlohmann::json());
  const std::string own = settle.is_number() ? " (settles in " + std::to_string(settle.get<uint32_t>()) + ")" : "";
  if (r.at("frames").is_null())
    return at + "never (" + std::to_string(r.at("frames_seen").get<uint32_t>()) + " frames seen)" + own;
  return at + std::to_string(r.at("frames").get<uint32_t>()) + own;
}

}  // namespace

std::vector<nlohmann::json> readPathFrames(const std::string& dir) {
  std::vector<nlohmann::json> out;
  std::ifstream in(fileOf(dir), std::ios::binary);
  if (!in) return out;
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  size_t start = 0;
  for (int line = 1; start < text.size(); ++line) {
    const size_t end = text.find('\n', start);
    nlohmann::json frame = nlohmann::json::parse(text.substr(start, end == std::string::npos ? end : end - start), nullptr,
                                                 /*allow_exceptions=*/false);
    const bool whole = end != std::string::npos && frame.is_object() && frame.contains("cell") && frame.contains("path_frame");
    if (!whole) {
      if (end == std::string::npos) break;  // the line a kill cut off
      throw std::runtime_error(fileOf(dir) + ":" + std::to_string(line) + ": not a path frame (a damaged file?)");
    }
    out.push_back(std::move(frame));
    start = end + 1;
  }
  return out;
}

void keepFinishedPathFrames(const std::string& dir, const std::set<std::pair<size_t, uint32_t>>& finished) {
  if (!std::filesystem::exists(fileOf(dir))) return;
  std::string kept;
  for (const nlohmann::json& f : readPathFrames(dir))
    if (finished.count({f.at("cell").get<size_t>(), f.value("round", 0u)})) kept += f.dump() + "\n";
  writeFileChecked(fileOf(dir), kept);
}

std::vector<nlohmann::json> mergedPathFrames(const std::vector<std::vector<nlohmann::json>>& shards,
                                             const std::set<std::pair<size_t, uint32_t>>& kept) {
  std::map<std::tuple<size_t, uint32_t, uint32_t>, const nlohmann::json*> byFrame;  // (cell, round, path frame)
  for (const std::vector<nlohmann::json>& frames : shards)
    for (const nlohmann::json& f : frames) {
      const size_t cell = f.at("cell").get<size_t>();
      const uint32_t round = f.value("round", 0u);
      if (kept.count({cell, round})) byFrame[{cell, round, f.at("path_frame").get<uint32_t>()}] = &f;
    }
  std::vector<nlohmann::json> out;
  out.reserve(byFrame.size());
  for (const auto& [where, f] : byFrame) out.push_back(*f);
  return out;
}

nlohmann::json pathSummary(const std::vector<nlohmann::json>& frames) {
  // cell -> round -> the round's frames by path frame
  std::map<size_t, std::map<uint32_t, std::map<uint32_t, const nlohmann::json*>>> byCell;
  for (const nlohmann::json& f : frames)
    byCell[f.at("cell").get<size_t>()][f.value("round", 0u)][f.at("path_frame").get<uint32_t>()] = &f;
  nlohmann::json cells = nlohmann::json::array();
  for (const auto& [cell, rounds] : byCell) {
    const nlohmann::json& first = *rounds.begin()->second.begin()->second;
    uint32_t count = 0;
    for (const auto& [round, list] : rounds) count = std::max(count, list.rbegin()->first + 1);
    std::vector<std::vector<double>> ms(count);
    std::vector<std::optional<double>> error(count);
    std::vector<bool> cut(count, false);
    std::vector<double> totals;
    bool detailedReplay = false;
    for (const auto& [round, list] : rounds) {
      double total = 0.0;
      const bool detailed = list.begin()->second->value("detailed", false);
      detailedReplay = detailedReplay || detailed;
      for (const auto& [f, frame] : list) {
        if (auto w = numberOr(*frame, "work_ms")) ms[f].push_back(*w), total += *w;
        cut[f] = frame->value("cut", false);
        if (detailed) error[f] = numberOr(*frame, "prediction_error_mean");
      }
      totals.push_back(total);
    }
    nlohmann::json frameMs = nlohmann::json::array(), errors = nlohmann::json::array(), cuts = nlohmann::json::array();
    double msSum = 0.0, errorSum = 0.0;
    uint32_t msCount = 0, errorCount = 0;
    for (uint32_t f = 0; f < count; ++f) {
      if (ms[f].empty()) {
        frameMs.push_back(nullptr);
      } else {
        const double m = spreadOf(ms[f]).median;
        frameMs.push_back(m), msSum += m, ++msCount;
      }
      errors.push_back(error[f] ? nlohmann::json(*error[f]) : nlohmann::json(nullptr));
      if (error[f]) errorSum += *error[f], ++errorCount;
      if (cut[f]) cuts.push_back(f);
    }
    nlohmann::json recovery = nlohmann::json::array();
    if (errorCount > 0)  // a strategy that predicts no end point has nothing to recover
      for (const CutRecovery& r : recoveryAfterCuts(error, cut)) recovery.push_back(toJson(r));
    cells.push_back({{"cell", cell},
                     {"label", first.value("label", "")},
                     {"scene", first.value("scene", "")},
                     {"strategy", first.value("strategy", "")},
                     {"sort_policy", first.value("sort_policy", "")},
                     {"camera_path", first.value("camera_path", "")},
                     {"frames", count},
                     {"rounds", rounds.size()},
                     {"frame_ms", frameMs},
                     {"mean_frame_ms", msCount ? nlohmann::json(msSum / msCount) : nlohmann::json(nullptr)},
                     {"total_ms", spreadOf(totals).median},
                     // The rounds' path totals: how far apart two cells' totals must be to tell them apart.
                     {"total_ms_spread", toJson(spreadOf(totals), totals.size() > 1)},
                     {"prediction_error", errors},
                     {"mean_prediction_error", errorCount ? nlohmann::json(errorSum / errorCount) : nlohmann::json(nullptr)},
                     {"detailed_replay", detailedReplay},
                     {"cuts", cuts},
                     {"recovery", recovery}});
  }
  return {{"recovery_tolerance", kRecoveryTolerance}, {"cells", cells}};
}

std::string pathSummaryMarkdown(const nlohmann::json& summary) {
  std::map<std::pair<std::string, std::string>, std::vector<const nlohmann::json*>> tables;
  for (const nlohmann::json& c : summary.at("cells")) tables[{c.at("camera_path"), c.at("scene")}].push_back(&c);
  const int tolerance = int(summary.value("recovery_tolerance", kRecoveryTolerance) * 100.0 + 0.5);
  std::string md;
  for (const auto& [key, cells] : tables) {
    md += "## " + key.second + " along " + key.first + " (" + std::to_string(cells.front()->at("frames").get<uint32_t>()) +
          " frames)\n\n";
    md += "| cell | mean frame ms | path total ms (rounds' min-max) | mean prediction error | frames to recover after a cut (within " +
          std::to_string(tolerance) + "% of before; in brackets, of the level it settles at) |\n|---|---:|---:|---:|---|\n";
    for (const nlohmann::json* c : cells) {
      std::string recovery;
      for (const nlohmann::json& r : c->at("recovery")) recovery += (recovery.empty() ? "" : ", ") + recoveryText(r);
      if (recovery.empty())
        recovery = c->at("cuts").empty()          ? "no cut"
                   : !c->at("detailed_replay") ? "not measured (--no-detail)"
                                               : "no prediction";
      const nlohmann::json& mean = c->at("mean_frame_ms");
      const nlohmann::json spread = c->value("total_ms_spread", nlohmann::json());
      const std::string range = spread.is_object() && spread.at("min").is_number()
                                    ? " (" + fixed(spread.at("min").get<double>(), 1) + "-" +
                                          fixed(spread.at("max").get<double>(), 1) + ")"
                                    : "";
      const nlohmann::json& error = c->at("mean_prediction_error");
      md += "| " + c->at("label").get<std::string>() + " | " + (mean.is_null() ? "n/a" : fixed(mean.get<double>(), 3)) +
            " | " + fixed(c->at("total_ms").get<double>(), 1) + range + " | " +
            (error.is_null() ? "no prediction" : fixed(error.get<double>(), 4)) + " | " +
            recovery + " |\n";
    }
    md += "\n";
  }
  return md;
}

bool writePathSummaries(const std::string& dir) {
  const std::vector<nlohmann::json> frames = readPathFrames(dir);
  if (frames.empty()) return false;
  const nlohmann::json summary = pathSummary(frames);
  writeFileChecked(dir + "/motion.json", summary.dump(1) + "\n");
  writeFileChecked(dir + "/motion.md", "# Bench along a camera path\n\n" + pathSummaryMarkdown(summary));
  return true;
}

void removePathSummaries(const std::string& dir) {
  for (const char* name : {"motion.json", "motion.md"}) std::filesystem::remove(dir + "/" + name);
}

}  // namespace raylab
