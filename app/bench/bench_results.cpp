#include "app/bench/bench_results.h"

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "app/bench/bench_resolution.h"
#include "app/bench/bench_rounds.h"
#include "renderer/checked_write.h"
#include "app/bench/bench_spread.h"
#include "renderer/git_revision.h"
#include "renderer/reorder/gpu_sort.h"
#include "renderer/settings/settings_table.h"
#include "renderer/stages.h"
#include "renderer/stats_json.h"

namespace raylab {
namespace {


// A cell's CSV columns by name, each formatted as an ostream formats it (6 significant digits).
class CsvRow {
 public:
  template <typename T>
  CsvRow& add(const std::string& column, const T& value) {
    std::ostringstream text;
    text << value;
    values_[column] = text.str();
    return *this;
  }
  const nlohmann::json& values() const { return values_; }

 private:
  nlohmann::json values_ = nlohmann::json::object();
};

std::string csvQuote(const std::string& s) { return "\"" + s + "\""; }

nlohmann::json csvRowOf(const VulkanContext& ctx, const BenchCell& cell, const std::string& view,
                        const SceneFacts& scene, const CellResult& r, const RunFacts& run) {
  const Settings& s = cell.settings;
  const auto& b = r.detailed.bounces;
  CsvRow row;
  row.add("device", csvQuote(ctx.info().name)).add("driver", csvQuote(ctx.info().driver)).add("git_revision", gitRevision());
  // Which GPU of the host made the row (shards on GPUs of one name): its --device number and identity.
  row.add("device_number", uint64_t(ctx.info().number)).add("device_uuid", ctx.info().uuid).add("device_pci", ctx.info().pciBus);
  // The settings' columns are their rows' (settings_table.h); the view is the one resolved (empty: the first).
  for (const auto& [column, text] : settingsCsvColumns(s)) row.add(column, text);
  row.add("view", view);
  row.add("paths_per_frame", uint64_t(s.width) * s.height * s.sppPerFrame);
  row.add("ser_reordering_hint", s.reordersInHardware() ? ctx.info().serReorderingHint : "");
  row.add("label", csvQuote(cell.label));
  // One round's times; the sweep's CSV replaces them with the medians and spreads over the rounds
  // (cellSummaries). Not measured is an empty cell, never 0 or -1 (issue 34): the megakernel and fused
  // trace+shade have no trace of bounces >= 1, a cell has no time of a stage it does not run.
  row.add("frame_ms_median", r.frameMs.median).add("frame_ms_min", r.frameMs.min).add("frame_ms_max", r.frameMs.max);
  row.add("trace_after_first_ms", csvNumber(r.traceAfterFirstMs ? std::optional(r.traceAfterFirstMs->median) : std::nullopt));
  for (const StageInfo& st : kStages)
    row.add(std::string(st.name) + "_ms",
            csvNumber(r.stageMs.count(st.name) ? std::optional(r.stageMs.at(st.name).median) : std::nullopt));
  // Figures of our traversal loop do not exist with the rt tracer, and none without the counting frame.
  auto loop = [&](double v) {
    return csvNumber(r.detailed.traversalStatsUnavailable.empty() ? measuredOrNone(v) : std::nullopt);
  };
  row.add("rays_per_second", r.raysPerSecond);
  row.add("trace_camera_rays_per_second",
          csvNumber(r.traceCameraRaysPerSecond ? std::optional(r.traceCameraRaysPerSecond->median) : std::nullopt));
  row.add("trace_bounce_rays_per_second",
          csvNumber(r.traceBounceRaysPerSecond ? std::optional(r.traceBounceRaysPerSecond->median) : std::nullopt));
  row.add("simt_efficiency", loop(meanOverBounces(b, &BounceStats::simtEfficiency, false)));
  row.add("virtual_warp_efficiency", loop(meanOverBounces(b, &BounceStats::virtualWarpEfficiency, false)));
  row.add("virtual_warp_efficiency_after_first", loop(meanOverBounces(b, &BounceStats::virtualWarpEfficiency, true)));
  row.add("prediction_error_mean", csvNumber(measuredOrNone(meanOverBounces(b, &BounceStats::predictionErrorMean, true))));
  row.add("prediction_error_median", csvNumber(measuredOrNone(meanOverBounces(b, &BounceStats::predictionErrorMedian, true))));
  row.add("cell_hit_rate", csvNumber(measuredOrNone(meanOverBounces(b, &BounceStats::cellHitRate, true))));
  auto detail = [&](double v) { return csvNumber(r.detailMeasured ? std::optional(v) : std::nullopt); };
  row.add("key_bits", detail(r.detailed.keyBits)).add("length_cache_bytes", detail(double(r.detailed.lengthCacheBytes)));
  row.add("final_rel_mse", csvNumber(r.finalRelMse));
  // Which bounces the policy's decided plan sorts after, e.g. "YNY-" (- : the last bounce).
  row.add("sorted_after", sortPlanText(r.sortedAfter));
  row.add("triangles", scene.triangles).add("bvh_nodes", scene.bvhNodes).add("bvh_bytes", scene.bvhBytes);
  row.add("scene_bytes", scene.sceneBytes).add("bvh_build_ms", scene.bvhBuildMs).add("scene_load_ms", scene.sceneLoadMs);
  row.add("tracer_setup_ms", scene.tracerSetupMs);
  row.add("wide_bvh_nodes", scene.wideBvhNodes).add("wide_bvh_bytes", scene.wideBvhBytes);
  // A camera path's replay (app/bench/bench_path.h): its name, frames and time (the frames' work time summed, and
  // per frame); empty for still frames.
  row.add("camera_path", r.path ? csvQuote(r.path->name) : std::string());
  row.add("path_frames", r.path ? std::to_string(r.path->frames) : std::string());
  row.add("path_total_ms", csvNumber(r.path ? std::optional(r.path->totalMs) : std::nullopt));
  row.add("path_mean_ms", csvNumber(r.path ? std::optional(r.path->meanMs) : std::nullopt));
  // The frame's fixed costs (issue 36): its commands, and the estimate of what they cost before any work,
  // dispatches x the run's empty dispatch (an estimate: a real stage's launch overlaps differently).
  row.add("dispatches", r.commands.dispatches()).add("indirect_dispatches", r.commands.indirectDispatches);
  row.add("barriers", r.commands.barriers).add("size_writes", r.commands.sizeWrites).add("submissions", r.submissions);
  row.add("empty_dispatch_us", csvNumber(run.emptyDispatchUs)).add("fixed_cost_ms", csvNumber(fixedCostMs(r.commands, run)));
  // How the radix scatter finds a digit's lanes: the frame's sorter takes the default, which resolves by the
  // device (RadixRank::Auto), so the row says which; empty where the settings sort no other way (from the
  // settings, not from whether a sort ran: the auto policy's choice follows timings).
  const bool radixSorts = s.sorts() && s.sort == SortAlgorithm::Radix;
  row.add("radix_rank", radixSorts ? radixRankName(GpuSorter::resolvedRadixRank(ctx, {})) : "");
  return row.values();
}

}  // namespace

nlohmann::json benchRecord(size_t cellIndex, uint32_t round, const VulkanContext& ctx, const BenchCell& cell, const std::string& view,
                           const SceneFacts& scene, const CellResult& r, const RunFacts& run) {
  const Settings& s = cell.settings;
  return {{"cell", cellIndex},
          {"round", round},
          {"paths_per_frame", uint64_t(s.width) * s.height * s.sppPerFrame},
          {"device", toJson(ctx.info())},
          {"git_revision", gitRevision()},
          {"view", view},
          {"label", cell.label},
          {"settings", toJson(cell.settings)},
          {"scene", toJson(scene)},
          {"result", toJson(r)},
          {"run_facts", toJson(run)},
          {"csv", csvRowOf(ctx, cell, view, scene, r, run)}};
}

BenchRecords readBenchRecords(const std::string& path) {
  BenchRecords out;
  std::ifstream in(path, std::ios::binary);
  if (!in) return out;
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  size_t start = 0;
  for (int line = 1; start < text.size(); ++line) {
    const size_t end = text.find('\n', start);
    const bool last = end == std::string::npos;  // no newline: the line a kill cut off
    nlohmann::json record = nlohmann::json::parse(text.substr(start, end == std::string::npos ? end : end - start),
                                                  nullptr, /*allow_exceptions=*/false);
    const bool whole = end != std::string::npos && record.is_object() && record.contains("cell") && record.contains("csv");
    if (!whole) {
      // A kill can cut the line being appended, and only that one: any other bad line is a damaged file.
      if (last) {
        out.droppedLastLine = true;
        break;
      }
      throw std::runtime_error(path + ":" + std::to_string(line) + ": not a bench record (a damaged file?)");
    }
    out.records.push_back(std::move(record));
    start = end + 1;
    out.wholeBytes = start;
  }
  return out;
}

std::string benchCsv(const std::vector<nlohmann::json>& records) {
  const std::vector<std::string> columns = benchCsvColumns();
  std::string csv;
  for (size_t i = 0; i < columns.size(); ++i) csv += (i ? "," : "") + columns[i];
  csv += "\n";
  for (const nlohmann::json& cell : cellSummaries(records)) {
    const nlohmann::json& values = cell.at("csv");
    for (size_t i = 0; i < columns.size(); ++i) csv += (i ? "," : "") + values.value(columns[i], std::string());
    csv += "\n";
  }
  return csv;
}

std::string cellsJsonl(const std::vector<nlohmann::json>& records) {
  std::string text;
  for (const nlohmann::json& cell : cellSummaries(records)) text += cell.dump() + "\n";
  return text;
}

namespace {
const char* const kSummaryFiles[] = {"results.csv", "cells.jsonl", "resolution.txt"};
}  // namespace

std::string writeSweepSummaries(const std::string& dir, const std::vector<nlohmann::json>& records) {
  const std::vector<nlohmann::json> cells = cellSummaries(records);
  std::string jsonl;
  for (const nlohmann::json& cell : cells) jsonl += cell.dump() + "\n";
  const std::string resolution = resolutionText(cells);
  writeFileChecked(dir + "/results.csv", benchCsv(records));
  writeFileChecked(dir + "/cells.jsonl", jsonl);
  writeFileChecked(dir + "/resolution.txt", resolution);
  return resolution;
}

void removeSweepSummaries(const std::string& dir) {
  for (const char* name : kSummaryFiles) std::filesystem::remove(dir + "/" + name);
}

}  // namespace raylab
