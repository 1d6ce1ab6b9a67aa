#include "app/bench_command.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>

#include "app/bench_measure.h"
#include "app/bench_sweep.h"
#include "app/scene_setup.h"
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

const char* kStages[] = {"generate", "trace", "learn", "shade", "keys", "oracle-trace", "sort", "reorder",
                         "accumulate", "tonemap", "megakernel", "setup", "counters", "trace+shade"};

void writeCsvHeader(std::ofstream& csv) {
  csv << "device,driver,git_revision,scene,view,width,height,bounces,spp_per_frame,kernel,tracer,ser,ser_reordering_hint,"
         "strategy,sort,label,"
         "frame_ms_median,frame_ms_min,frame_ms_max,trace_after_first_ms";
  for (const char* s : kStages) csv << "," << s << "_ms";
  csv << ",rays_per_second,simt_efficiency,virtual_warp_efficiency,virtual_warp_efficiency_after_first,"
         "prediction_error_mean,prediction_error_median,cell_hit_rate,key_bits,length_cache_bytes,final_rel_mse,"
         "sort_policy,sorted_after,triangles,bvh_nodes,bvh_bytes,scene_bytes,bvh_build_ms,scene_load_ms,tracer_setup_ms,"
         "sort_bits,learn_every,fusion,compaction,trace_shade\n";
}

std::string csvQuote(const std::string& s) { return "\"" + s + "\""; }

void writeCsvRow(std::ofstream& csv, const VulkanContext& ctx, const BenchCell& cell, const std::string& view,
                 const SceneFacts& scene, const CellResult& r) {
  const Settings& s = cell.settings;
  const auto& b = r.detailed.bounces;
  csv << csvQuote(ctx.info().name) << "," << csvQuote(ctx.info().driver) << "," << gitRevision() << ","
      << csvQuote(s.scene) << "," << view << "," << s.width << "," << s.height << "," << s.bounces << ","
      << s.sppPerFrame << "," << toString(s.kernel) << "," << toString(s.tracer) << "," << toString(s.ser) << ","
      << (s.reordersInHardware() ? ctx.info().serReorderingHint : "") << "," << toString(s.strategy) << "," << toString(s.sort) << ","
      << csvQuote(cell.label) << "," << r.frameMs.median << "," << r.frameMs.min << "," << r.frameMs.max << ","
      << r.traceAfterFirstMs.median;
  for (const char* st : kStages) csv << "," << (r.stageMs.count(st) ? r.stageMs.at(st).median : 0.0);
  // Figures of our traversal loop do not exist with the rt tracer: written as n/a, never as numbers.
  auto loop = [&](double v) { return r.detailed.traversalStatsUnavailable.empty() ? std::to_string(v) : std::string("n/a"); };
  csv << "," << r.raysPerSecond << "," << loop(meanOverBounces(b, &BounceStats::simtEfficiency, false)) << ","
      << loop(meanOverBounces(b, &BounceStats::virtualWarpEfficiency, false)) << ","
      << loop(meanOverBounces(b, &BounceStats::virtualWarpEfficiency, true)) << ","
      << meanOverBounces(b, &BounceStats::predictionErrorMean, true) << ","
      << meanOverBounces(b, &BounceStats::predictionErrorMedian, true) << "," << meanOverBounces(b, &BounceStats::cellHitRate, true)
      << "," << r.detailed.keyBits << "," << r.detailed.lengthCacheBytes << ","
      << r.finalRelMse << "," << toString(s.sortPolicy) << ",";
  // Which bounces the policy sorted after in the last timed frame, e.g. "YNY-" (- : the last bounce).
  for (size_t k = 0; k < r.sortedAfter.size(); ++k) csv << (k + 1 == r.sortedAfter.size() ? '-' : r.sortedAfter[k] ? 'Y' : 'N');
  csv << "," << scene.triangles << "," << scene.bvhNodes << "," << scene.bvhBytes << "," << scene.sceneBytes << ","
      << scene.bvhBuildMs << "," << scene.sceneLoadMs << "," << scene.tracerSetupMs << "," << s.sortBits << "," << s.learnEvery << "," << toString(s.fusion) << ","
      << toString(s.compaction) << "," << toString(s.traceShade) << "\n";
  csv.flush();
}

}  // namespace

int runBenchCommand(const std::vector<std::string>& args) {
  if (!args.empty() && (args[0] == "--help" || args[0] == "-h")) {
    std::printf("usage: raylab bench [options]\n%s", benchHelp().c_str());
    return kExitOk;
  }
  BenchPlan plan;
  try {
    plan = parseBenchPlan(args);
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
  std::ofstream csv(plan.outDir + "/results.csv");
  std::ofstream jsonl(plan.outDir + "/results.jsonl");
  writeCsvHeader(csv);

  size_t done = 0, failed = 0;
  auto start = std::chrono::steady_clock::now();
  for (size_t ci = 0; ci < plan.cases.size(); ++ci) {
    std::vector<const BenchCell*> cells;
    for (const BenchCell& c : plan.cells)
      if (c.caseIndex == ci) cells.push_back(&c);
    try {
      Settings caseSettings = cells.front()->settings;
      auto msSince = [](std::chrono::steady_clock::time_point t) {
        return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
      };
      auto loadStart = std::chrono::steady_clock::now();
      LoadedScene loaded = loadSceneForSettings(caseSettings);
      double loadMs = msSince(loadStart);
      auto setupStart = std::chrono::steady_clock::now();
      PathTracer tracer(ctx, loaded.scene, caseSettings, loaded.view);
      SceneFacts facts = sceneFactsOf(tracer.scene(), loadMs, msSince(setupStart));
      std::fprintf(stderr, "%s: %llu triangles, BVH %.1f MB (built in %.0f ms), scene made in %.0f ms\n",
                   loaded.scene.name.c_str(), static_cast<unsigned long long>(facts.triangles), facts.bvhBytes / 1e6,
                   facts.bvhBuildMs, facts.sceneLoadMs);
      // The reference and the error curve depend on the path length: made again for each bounce count.
      uint32_t referenceBounces = 0;
      std::vector<glm::vec3> reference;
      std::vector<double> errorCurve;
      for (const BenchCell* cell : cells) {
        if (cell->settings.bounces != referenceBounces) {
          Settings group = caseSettings;
          group.bounces = referenceBounces = cell->settings.bounces;
          reference = renderReference(tracer, group, plan.referenceSpp);
          errorCurve = measureErrorCurve(tracer, group, plan.timedFrames, reference);
        }
        ++done;
        CellResult r = measureCell(tracer, cell->settings, plan.warmupFrames, plan.timedFrames, reference,
                                   errorCurve, plan.detailFrame);
        writeCsvRow(csv, ctx, *cell, loaded.view.name, facts, r);
        nlohmann::json row = {{"device", toJson(ctx.info())}, {"git_revision", gitRevision()},
                              {"view", loaded.view.name},      {"label", cell->label},
                              {"settings", toJson(cell->settings)}, {"scene", toJson(facts)},
                              {"result", toJson(r)}};
        jsonl << row.dump() << "\n";
        jsonl.flush();
        double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::fprintf(stderr, "[%zu/%zu %.0fs] %s@%s b=%u %-32s frame %.2f ms, trace(b>=1) %.2f ms\n", done,
                     plan.cells.size(), elapsed, loaded.scene.name.c_str(), loaded.view.name.c_str(),
                     cell->settings.bounces, cell->label.c_str(), r.frameMs.median, r.traceAfterFirstMs.median);
      }
    } catch (const std::exception& e) {
      failed += cells.size();
      done += cells.size();
      std::fprintf(stderr, "raylab bench: case %s@%s failed: %s\n", plan.cases[ci].scene.c_str(),
                   plan.cases[ci].view.c_str(), e.what());
    }
  }
  std::printf("bench: %zu cells, %zu failed; results in %s/results.csv and results.jsonl\n", plan.cells.size(),
              failed, plan.outDir.c_str());
  if (ctx.validationErrors() > 0) return kExitValidation;
  return failed == 0 ? kExitOk : kExitFailure;
}

}  // namespace raylab
