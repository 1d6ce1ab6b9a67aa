#include "app/bench/bench_command.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <tuple>

#include "app/bench/bench_charts_run.h"
#include "app/bench/bench_measure.h"
#include "app/bench/bench_merge.h"
#include "app/bench/bench_path.h"
#include "app/bench/bench_path_summary.h"
#include "app/bench/bench_shard.h"
#include "app/bench/bench_results.h"
#include "app/bench/bench_resume.h"
#include "app/bench/bench_rounds.h"
#include "app/bench/bench_spread.h"
#include "app/bench/bench_sweep.h"
#include "app/scene_setup.h"
#include "renderer/checked_write.h"
#include "renderer/device_limits.h"
#include "renderer/rt_tracer.h"
#include "renderer/stats_json.h"
#include "renderer/vk/empty_dispatch.h"
#include "renderer/git_revision.h"

namespace raylab {
namespace {

// What a case's reference image and error curve depend on besides the scene: one per group of cells.
struct ReferenceGroup {
  uint32_t bounces = 0, width = 0, height = 0, spp = 0;
  bool operator==(const ReferenceGroup& o) const {
    return bounces == o.bounces && width == o.width && height == o.height && spp == o.spp;
  }
  void applyTo(Settings& s) const {
    s.bounces = bounces;
    s.width = width;
    s.height = height;
    s.sppPerFrame = spp;
  }
};
ReferenceGroup referenceGroupOf(const Settings& s) { return {s.bounces, s.width, s.height, s.sppPerFrame}; }

// The reference's samples per frame: all of them in one frame where that is few paths, else as many as keep
// a frame within the cell's own path count or 2M paths, whichever is more. 64 spp at 4096x2048 would be half
// a billion paths in one frame, past the settings' limit and any device's memory.
uint32_t referenceSppPerFrame(const Settings& base, uint32_t spp) {
  const uint64_t pixels = std::max<uint64_t>(1, uint64_t(base.width) * base.height);
  const uint64_t budget = std::max<uint64_t>(pixels * base.sppPerFrame, uint64_t(1) << 21);
  const uint64_t fits = std::max<uint64_t>(1, std::min<uint64_t>(budget, SettingLimits::kMaxPathsPerFrame) / pixels);
  return static_cast<uint32_t>(std::min<uint64_t>({spp, SettingLimits::kMaxSpp, fits}));
}

// The reference image of a case: the megakernel with many samples.
std::vector<glm::vec3> renderReference(PathTracer& tracer, const Settings& base, uint32_t spp) {
  Settings ref = base;
  ref.kernel = Kernel::Megakernel;
  ref.strategy = KeyStrategy::None;
  ref.seed = base.seed + 1000003;  // independent of the measured frames' samples
  ref.sppPerFrame = referenceSppPerFrame(base, spp);
  tracer.applySettings(ref);
  tracer.restartAccumulation();
  for (uint32_t done = 0; done < spp; done += ref.sppPerFrame) tracer.renderFrame();
  std::vector<glm::vec3> image = tracer.readRadiance();
  tracer.applySettings(base);
  return image;
}

// `--resume DIR` taken out of the arguments (empty when absent).
std::string takeResume(std::vector<std::string>& args) {
  std::string dir;
  for (size_t i = 0; i < args.size(); ++i) {
    if (args[i] != "--resume") continue;
    if (i + 1 >= args.size()) throw UsageError("--resume needs the folder of the sweep to continue");
    dir = args[i + 1];
    args.erase(args.begin() + static_cast<std::ptrdiff_t>(i), args.begin() + static_cast<std::ptrdiff_t>(i) + 2);
    --i;
  }
  return dir;
}

// The arguments sweep.json records: what defines the sweep, not where it goes.
std::vector<std::string> withoutOutDir(std::vector<std::string> args) {
  for (size_t i = 0; i + 1 < args.size(); ++i)
    if (args[i] == "--out-dir") args.erase(args.begin() + static_cast<std::ptrdiff_t>(i), args.begin() + static_cast<std::ptrdiff_t>(i) + 2), --i;
  return args;
}

// The plan to run: from the arguments, or with --resume DIR from DIR's sweep.json (the arguments recorded
// there when none are given), refused unless it is the sweep DIR recorded at this build. Throws UsageError.
BenchPlan planFor(std::vector<std::string> args, std::string* resumeDir, std::vector<std::string>* recordArgs,
                  BenchShard* shard) {
  *resumeDir = takeResume(args);
  const bool shardGiven = std::find(args.begin(), args.end(), "--shard") != args.end();
  *shard = takeShard(args);
  if (resumeDir->empty()) {
    *recordArgs = withoutOutDir(args);
    return parseBenchPlan(args);
  }
  if (std::find(args.begin(), args.end(), "--out-dir") != args.end())
    throw UsageError("--resume DIR continues the sweep in DIR: leave out --out-dir");
  SweepRecord recorded;
  try {
    recorded = readSweepRecord(*resumeDir);
  } catch (const UsageError& e) {
    throw UsageError(std::string("--resume ") + e.what());
  }
  if (args.empty()) args = recorded.args;
  if (!shardGiven) *shard = recorded.shard;
  if (!(*shard == recorded.shard))
    throw UsageError("--resume " + *resumeDir + ": it holds shard " + recorded.shard.text() + " of its sweep, not " +
                     shard->text());
  *recordArgs = withoutOutDir(args);
  BenchPlan plan = parseBenchPlan(args);
  plan.outDir = *resumeDir;
  if (std::string why = resumeRefusal(recorded, plan); !why.empty()) throw UsageError("--resume " + *resumeDir + ": " + why);
  return plan;
}

// A cell's round: what results.jsonl records once, and a resume skips.
using CellRound = std::pair<size_t, uint32_t>;

// A case's reference images and error curves, one per group of cells (bounces, size, spp), made when a cell of
// the group first needs them: the rounds run a case's cells in mixed order, and a reference made again at
// every change of group would cost more than the cells.
struct ReferenceCache {
  PathTracer& tracer;
  const BenchPlan& plan;
  Settings caseSettings;
  std::map<std::tuple<uint32_t, uint32_t, uint32_t, uint32_t>, std::pair<std::vector<glm::vec3>, std::vector<double>>> made;

  const std::pair<std::vector<glm::vec3>, std::vector<double>>& of(const Settings& cell) {
    const ReferenceGroup g = referenceGroupOf(cell);
    const auto key = std::make_tuple(g.bounces, g.width, g.height, g.spp);
    if (auto it = made.find(key); it != made.end()) return it->second;
    Settings groupSettings = caseSettings;
    g.applyTo(groupSettings);
    std::vector<glm::vec3> reference = renderReference(tracer, groupSettings, plan.referenceSpp);
    std::vector<double> curve = measureErrorCurve(tracer, groupSettings, plan.timedFrames, reference);
    return made[key] = {std::move(reference), std::move(curve)};
  }
};

// Runs every cell's round not in `finished`, case by case and, within a case, round by round (each round
// its cells in roundOrder's order), appending each result durably to `jsonl` as it ends; returns how many
// cells failed. A case that fails (a scene that does not load, a device error) fails its cells and the sweep
// goes on; a result that cannot be stored (WriteError) ends the sweep. Rounds interleave within a case, not
// across cases: a case's scene and BVH are built once, and cells are compared within their case.
size_t runCells(const BenchPlan& plan, const BenchShard& shard, const VulkanContext& ctx, const RunFacts& run,
                const std::set<CellRound>& finished, AppendFile& jsonl, AppendFile* pathFrames) {
  size_t total = 0;  // this shard's cells' rounds
  for (size_t i = 0; i < plan.cells.size(); ++i) total += shard.contains(i) ? plan.rounds : 0;
  size_t done = finished.size(), failed = 0;
  auto start = std::chrono::steady_clock::now();
  for (size_t ci = 0; ci < plan.cases.size(); ++ci) {
    std::vector<size_t> cells;  // indices into plan.cells: this case's cells of this shard
    for (size_t i = 0; i < plan.cells.size(); ++i)
      if (plan.cells[i].caseIndex == ci && shard.contains(i)) cells.push_back(i);
    size_t left = 0;
    for (size_t i : cells)
      for (uint32_t round = 0; round < plan.rounds; ++round) left += !finished.count({i, round});
    if (left == 0) continue;
    try {
      Settings caseSettings = plan.cells[cells.front()].settings;
      auto msSince = [](std::chrono::steady_clock::time_point t) {
        return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
      };
      auto loadStart = std::chrono::steady_clock::now();
      LoadedScene loaded = loadSceneForSettings(caseSettings);
      double loadMs = msSince(loadStart);
      auto setupStart = std::chrono::steady_clock::now();
      // With --camera-path every cell replays the path, resolved for this case's scene (app/bench/bench_path.h).
      std::optional<PathRender> path;
      if (!plan.cameraPath.empty()) {
        path = pathRenderFor(plan.cameraPath, loaded.scene, plan.pathFramesCap);
        loaded.view = cameraAt(path->path, 0, path->up).view;
        loaded.view.name = path->path.name;  // the CSV's view: the path's
      }
      PathTracer tracer(ctx, loaded.scene, caseSettings, loaded.view);
      SceneFacts facts = sceneFactsOf(tracer.scene(), loadMs, msSince(setupStart));
      std::fprintf(stderr, "%s: %llu triangles, BVH %.1f MB (built in %.0f ms), wide BVH %.1f MB, scene made in %.0f ms\n",
                   loaded.scene.name.c_str(), static_cast<unsigned long long>(facts.triangles), facts.bvhBytes / 1e6,
                   facts.bvhBuildMs, facts.wideBvhBytes / 1e6, facts.sceneLoadMs);
      // The reference and the error curve depend on the path length, the image size and the samples per
      // frame; the BVH layout changes no converged image: one reference serves both.
      ReferenceCache references{tracer, plan, caseSettings, {}};
      for (uint32_t round = 0; round < plan.rounds; ++round)
        for (size_t position : roundOrder(cells.size(), round)) {
          const size_t index = cells[position];
          if (finished.count({index, round})) continue;
          const BenchCell& cell = plan.cells[index];
          ++done;
          CellResult r;
          if (path) {
            // The detailed replay is the first round's; its work times hold beside the others' (bench_path.h).
            PathCellResult p = measurePathCell(tracer, cell.settings, *path, plan.warmupFrames, plan.detailFrame && round == 0);
            std::string lines;
            for (nlohmann::json& frame : p.frames) {
              nlohmann::json line = {{"cell", index},         {"round", round},
                                     {"label", cell.label},   {"scene", loaded.scene.name},
                                     {"strategy", toString(cell.settings.strategy)},
                                     {"sort_policy", toString(cell.settings.sortPolicy)},
                                     {"camera_path", path->path.name}};
              line.update(frame);
              lines += line.dump() + "\n";
            }
            pathFrames->append(lines, /*durable=*/true);  // before the record: a resume keeps both or neither
            r = std::move(p.cell);
          } else {
            const auto& [reference, errorCurve] = references.of(cell.settings);
            // The counting frame's figures are no time: the first round measures them, later rounds skip it.
            r = measureCell(tracer, cell.settings, plan.warmupFrames, plan.timedFrames, reference, errorCurve,
                            plan.detailFrame && round == 0);
          }
          jsonl.append(benchRecord(index, round, ctx, cell, loaded.view.name, facts, r, run).dump() + "\n", /*durable=*/true);
          double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
          const std::string later =
              screenNumber(r.traceAfterFirstMs ? std::optional(r.traceAfterFirstMs->median) : std::nullopt);
          std::fprintf(stderr, "[%zu/%zu %.0fs] round %u/%u %s@%s %ux%u spp=%u b=%u %-32s frame %.2f ms, trace(b>=1) %s%s%s\n",
                       done, total, elapsed, round + 1, plan.rounds, loaded.scene.name.c_str(), loaded.view.name.c_str(),
                       cell.settings.width, cell.settings.height, cell.settings.sppPerFrame, cell.settings.bounces,
                       cell.label.c_str(), r.frameMs.median, later.c_str(), later == "n/a" ? "" : " ms",
                       r.policySettled ? "" : " (auto still exploring when timed)");
          if (r.path)
            std::fprintf(stderr, "    along %s: %u frames, %.1f ms in all, %.2f ms a frame\n", r.path->name.c_str(),
                         r.path->frames, r.path->totalMs, r.path->meanMs);
        }
    } catch (const WriteError&) {
      throw;
    } catch (const std::exception& e) {
      failed += cells.size();
      done += left;
      std::fprintf(stderr, "raylab bench: case %s@%s failed: %s\n", plan.cases[ci].scene.c_str(),
                   plan.cases[ci].view.c_str(), e.what());
    }
  }
  return failed;
}

}  // namespace

int runBenchCommand(const std::vector<std::string>& args) {
  if (!args.empty() && (args[0] == "--help" || args[0] == "-h")) {
    std::printf("%s", benchHelp().c_str());  // it starts with its usage line
    return kExitOk;
  }
  if (std::find(args.begin(), args.end(), "--merge") != args.end()) return runBenchMerge(args);
  BenchPlan plan;
  std::string resumeDir;
  std::vector<std::string> recordArgs;
  BenchShard shard;
  try {
    plan = planFor(args, &resumeDir, &recordArgs, &shard);
  } catch (const UsageError& e) {
    printUsageError("raylab bench", e.what());
    return kExitUsage;
  }
  VulkanContext ctx(contextOptionsFor(plan.common));
  for (const BenchCell& cell : plan.cells)  // the whole plan, whichever shard: one refusal for every shard
    if (std::string why = unsupportedSettings(ctx.info(), cell.settings); !why.empty()) {
      std::fprintf(stderr, "raylab bench: %s\n", why.c_str());
      return kExitUsage;
    } else if (std::string beyond = pathsBeyondDevice(ctx.info(), cell.settings); !beyond.empty()) {
      // Every cell is checked before the first renders: a size the device cannot run is a bad sweep.
      std::fprintf(stderr, "raylab bench: cell '%s': %s\n", cell.label.c_str(), beyond.c_str());
      return kExitUsage;
    }
  std::filesystem::create_directories(plan.outDir);  // once the sweep is known to run: a refused one leaves no folder
  const std::string jsonlPath = plan.outDir + "/results.jsonl";
  size_t failed = 0;
  std::string resolution;
  // Once per run, before the cells: what a dispatch costs before any work, which each row's fixed_cost_ms
  // multiplies by its dispatches.
  RunFacts runFacts;
  // On a CPU device (lavapipe) the figure says nothing of a GPU, and with the validation layer on (the tests)
  // the default 4,608 validated dispatches took seconds a bench (cli.study_shards: 19 -> 63 s in CI's run):
  // a shorter measurement there (768 dispatches), the full one on a GPU.
  runFacts.emptyDispatchUs = ctx.info().isCpu ? measureEmptyDispatchUs(ctx, 64, 3) : measureEmptyDispatchUs(ctx);
  try {
    // results.csv and the other summaries exist only for a sweep that ended: an old one beside a new,
    // unfinished JSONL would lie.
    removeSweepSummaries(plan.outDir);
    removePathSummaries(plan.outDir);
    std::set<CellRound> finished;
    if (resumeDir.empty()) {
      writeSweepRecord(plan.outDir, plan, recordArgs, shard);
    } else {
      BenchRecords old = readBenchRecords(jsonlPath);
      if (old.droppedLastLine) {  // a kill cut the last line: keep the whole ones, run that cell again
        std::ifstream in(jsonlPath, std::ios::binary);
        const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        writeFileChecked(jsonlPath, std::string_view(text).substr(0, old.wholeBytes));
      }
      for (const nlohmann::json& r : old.records) finished.insert({r.at("cell").get<size_t>(), roundOf(r)});
      keepFinishedPathFrames(plan.outDir, finished);
      size_t shardCells = 0;
      for (size_t i = 0; i < plan.cells.size(); ++i) shardCells += shard.contains(i);
      std::fprintf(stderr, "raylab bench: resuming %s: %zu of %zu cell rounds done (%zu cells x %u rounds)%s\n",
                   resumeDir.c_str(), finished.size(), shardCells * plan.rounds, shardCells, plan.rounds,
                   old.droppedLastLine ? " (a cut-off last line dropped)" : "");
    }
    AppendFile jsonl(jsonlPath, resumeDir.empty() ? AppendFile::Start::Empty : AppendFile::Start::Keep);
    std::optional<AppendFile> pathFrames;
    if (!plan.cameraPath.empty())
      pathFrames.emplace(plan.outDir + "/" + kPathFramesFile, resumeDir.empty() ? AppendFile::Start::Empty : AppendFile::Start::Keep);
    failed = runCells(plan, shard, ctx, runFacts, finished, jsonl, pathFrames ? &*pathFrames : nullptr);
    jsonl.close();
    if (pathFrames) pathFrames->close();
    resolution = writeSweepSummaries(plan.outDir, readBenchRecords(jsonlPath).records);
    if (pathFrames && writePathSummaries(plan.outDir)) resolution += "bench: along the camera path: " + plan.outDir + "/motion.md\n";
  } catch (const WriteError& e) {
    std::fprintf(stderr, "raylab bench: %s\nraylab bench: the cells measured so far are in %s; `raylab bench --resume %s` "
                 "continues the sweep\n", e.what(), jsonlPath.c_str(), plan.outDir.c_str());
    return kExitFailure;
  }
  size_t cells = 0;
  for (size_t i = 0; i < plan.cells.size(); ++i) cells += shard.contains(i);
  std::printf("%sbench: %zu cells%s x %u rounds, %zu failed; results in %s/results.csv and results.jsonl\n",
              resolution.c_str(), cells,
              shard.whole() ? "" : (" (shard " + shard.text() + " of " + std::to_string(plan.cells.size()) + ")").c_str(),
              plan.rounds, failed, plan.outDir.c_str());
  if (runFacts.emptyDispatchUs)
    std::printf("bench: an empty dispatch and its barrier cost %.2f us on %s (fixed_cost_ms = dispatches x this, an "
                "estimate)\n", *runFacts.emptyDispatchUs, ctx.info().name.c_str());
  else
    std::printf("bench: the device has no timestamps: no empty-dispatch cost, fixed_cost_ms stays empty\n");
  std::fflush(stdout);  // before the chart script's own lines
  const bool chartsFailed = plan.charts && !drawAndReportCharts(plan.outDir);
  if (ctx.validationErrors() > 0) return kExitValidation;
  return failed == 0 && !chartsFailed ? kExitOk : kExitFailure;
}

}  // namespace raylab
