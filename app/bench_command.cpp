#include "app/bench_command.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <set>

#include "app/bench_measure.h"
#include "app/bench_results.h"
#include "app/bench_resume.h"
#include "app/bench_sweep.h"
#include "app/scene_setup.h"
#include "renderer/checked_write.h"
#include "renderer/rt_tracer.h"
#include "renderer/stats_json.h"
#include "renderer/git_revision.h"

namespace raylab {
namespace {

// The reference image of a case: the megakernel with many samples.
std::vector<glm::vec3> renderReference(PathTracer& tracer, const Settings& base, uint32_t spp) {
  Settings ref = base;
  ref.kernel = Kernel::Megakernel;
  ref.strategy = KeyStrategy::None;
  ref.seed = base.seed + 1000003;  // independent of the measured frames' samples
  ref.sppPerFrame = std::min<uint32_t>(spp, SettingLimits::kMaxSpp);
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
BenchPlan planFor(std::vector<std::string> args, std::string* resumeDir, std::vector<std::string>* recordArgs) {
  *resumeDir = takeResume(args);
  if (resumeDir->empty()) {
    *recordArgs = withoutOutDir(args);
    return parseBenchPlan(args);
  }
  if (std::find(args.begin(), args.end(), "--out-dir") != args.end())
    throw UsageError("--resume DIR continues the sweep in DIR: leave out --out-dir");
  const SweepRecord recorded = readSweepRecord(*resumeDir);
  if (args.empty()) args = recorded.args;
  *recordArgs = withoutOutDir(args);
  BenchPlan plan = parseBenchPlan(args);
  plan.outDir = *resumeDir;
  if (std::string why = resumeRefusal(recorded, plan); !why.empty()) throw UsageError("--resume " + *resumeDir + ": " + why);
  return plan;
}

// Runs every cell not in `finished`, case by case, appending each result durably to `jsonl` as it ends;
// returns how many cells failed. A case that fails (a scene that does not load, a device error) fails its
// cells and the sweep goes on; a result that cannot be stored (WriteError) ends the sweep.
size_t runCells(const BenchPlan& plan, const VulkanContext& ctx, const std::set<size_t>& finished, AppendFile& jsonl) {
  size_t done = finished.size(), failed = 0;
  auto start = std::chrono::steady_clock::now();
  for (size_t ci = 0; ci < plan.cases.size(); ++ci) {
    std::vector<size_t> cells;  // indices into plan.cells
    for (size_t i = 0; i < plan.cells.size(); ++i)
      if (plan.cells[i].caseIndex == ci && !finished.count(i)) cells.push_back(i);
    if (cells.empty()) continue;
    try {
      Settings caseSettings = plan.cells[cells.front()].settings;
      auto msSince = [](std::chrono::steady_clock::time_point t) {
        return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
      };
      auto loadStart = std::chrono::steady_clock::now();
      LoadedScene loaded = loadSceneForSettings(caseSettings);
      double loadMs = msSince(loadStart);
      auto setupStart = std::chrono::steady_clock::now();
      PathTracer tracer(ctx, loaded.scene, caseSettings, loaded.view);
      SceneFacts facts = sceneFactsOf(tracer.scene(), loadMs, msSince(setupStart));
      std::fprintf(stderr, "%s: %llu triangles, BVH %.1f MB (built in %.0f ms), wide BVH %.1f MB, scene made in %.0f ms\n",
                   loaded.scene.name.c_str(), static_cast<unsigned long long>(facts.triangles), facts.bvhBytes / 1e6,
                   facts.bvhBuildMs, facts.wideBvhBytes / 1e6, facts.sceneLoadMs);
      // The reference and the error curve depend on the path length: made again for each bounce count.
      uint32_t referenceBounces = 0;
      std::vector<glm::vec3> reference;
      std::vector<double> errorCurve;
      for (size_t index : cells) {
        const BenchCell& cell = plan.cells[index];
        if (cell.settings.bounces != referenceBounces) {
          Settings group = caseSettings;
          group.bounces = referenceBounces = cell.settings.bounces;
          reference = renderReference(tracer, group, plan.referenceSpp);
          errorCurve = measureErrorCurve(tracer, group, plan.timedFrames, reference);
        }
        ++done;
        CellResult r = measureCell(tracer, cell.settings, plan.warmupFrames, plan.timedFrames, reference,
                                   errorCurve, plan.detailFrame);
        jsonl.append(benchRecord(index, ctx, cell, loaded.view.name, facts, r).dump() + "\n", /*durable=*/true);
        double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::fprintf(stderr, "[%zu/%zu %.0fs] %s@%s b=%u %-32s frame %.2f ms, trace(b>=1) %.2f ms\n", done,
                     plan.cells.size(), elapsed, loaded.scene.name.c_str(), loaded.view.name.c_str(),
                     cell.settings.bounces, cell.label.c_str(), r.frameMs.median, r.traceAfterFirstMs.median);
      }
    } catch (const WriteError&) {
      throw;
    } catch (const std::exception& e) {
      failed += cells.size();
      done += cells.size();
      std::fprintf(stderr, "raylab bench: case %s@%s failed: %s\n", plan.cases[ci].scene.c_str(),
                   plan.cases[ci].view.c_str(), e.what());
    }
  }
  return failed;
}

}  // namespace

int runBenchCommand(const std::vector<std::string>& args) {
  if (!args.empty() && (args[0] == "--help" || args[0] == "-h")) {
    std::printf("usage: raylab bench [options]\n%s", benchHelp().c_str());
    return kExitOk;
  }
  BenchPlan plan;
  std::string resumeDir;
  std::vector<std::string> recordArgs;
  try {
    plan = planFor(args, &resumeDir, &recordArgs);
  } catch (const UsageError& e) {
    std::fprintf(stderr, "raylab bench: %s\n\n%s", e.what(), benchHelp().c_str());
    return kExitUsage;
  }
  std::filesystem::create_directories(plan.outDir);
  VulkanContext ctx(contextOptionsFor(plan.common));
  for (const BenchCell& cell : plan.cells)
    if (std::string why = unsupportedSettings(ctx.info(), cell.settings); !why.empty()) {
      std::fprintf(stderr, "raylab bench: %s\n", why.c_str());
      return kExitUsage;
    }
  const std::string jsonlPath = plan.outDir + "/results.jsonl", csvPath = plan.outDir + "/results.csv";
  size_t failed = 0;
  try {
    // results.csv exists only for a sweep that ended: an old one beside a new, unfinished JSONL would lie.
    std::filesystem::remove(csvPath);
    std::set<size_t> finished;
    if (resumeDir.empty()) {
      writeSweepRecord(plan.outDir, plan, recordArgs);
    } else {
      BenchRecords old = readBenchRecords(jsonlPath);
      if (old.droppedLastLine) {  // a kill cut the last line: keep the whole ones, run that cell again
        std::ifstream in(jsonlPath, std::ios::binary);
        const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        writeFileChecked(jsonlPath, std::string_view(text).substr(0, old.wholeBytes));
      }
      for (const nlohmann::json& r : old.records) finished.insert(r.at("cell").get<size_t>());
      std::fprintf(stderr, "raylab bench: resuming %s: %zu of %zu cells done%s\n", resumeDir.c_str(), finished.size(),
                   plan.cells.size(), old.droppedLastLine ? " (a cut-off last line dropped)" : "");
    }
    AppendFile jsonl(jsonlPath, resumeDir.empty() ? AppendFile::Start::Empty : AppendFile::Start::Keep);
    failed = runCells(plan, ctx, finished, jsonl);
    jsonl.close();
    writeFileChecked(csvPath, benchCsv(readBenchRecords(jsonlPath).records));
  } catch (const WriteError& e) {
    std::fprintf(stderr, "raylab bench: %s\nraylab bench: the cells measured so far are in %s; `raylab bench --resume %s` "
                 "continues the sweep\n", e.what(), jsonlPath.c_str(), plan.outDir.c_str());
    return kExitFailure;
  }
  std::printf("bench: %zu cells, %zu failed; results in %s/results.csv and results.jsonl\n", plan.cells.size(),
              failed, plan.outDir.c_str());
  if (ctx.validationErrors() > 0) return kExitValidation;
  return failed == 0 ? kExitOk : kExitFailure;
}

}  // namespace raylab
