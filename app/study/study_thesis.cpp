#include "app/study/study_thesis.h"

#include <cstdio>
#include <filesystem>

#include "app/bench/bench_charts_run.h"
#include "app/bench/bench_command.h"
#include "app/cli_options.h"
#include "app/command_errors.h"

namespace raylab {

std::vector<ThesisSweep> thesisPlan(const StudyOptions& o, bool cpu) {
  if (o.target != "temple")
    throw UsageError("--thesis re-measures the source study's temple views: raylab study temple --thesis");
  if (o.sizes.size() > 1 || !o.bounces.empty() || !o.strategies.empty() || o.quick || !o.shard.whole())
    throw UsageError("--thesis takes the thesis's own settings: at most one --sizes value (the tests' small one), "
                     "no --bounces, --strategies, --quick or --shard");
  const std::string size = !o.sizes.empty() ? o.sizes.front() : cpu ? "256x128" : "2048x1024";
  // The thesis's Examples 1-3 are an alley, the middle of the scene and a view with openings.
  const std::vector<std::string> common = {
      "--cases", "temple@alley,temple@hall,temple@openings", "--size", size,
      "--bounces", "4", "--sorts", "bitonic,radix", "--timed-frames", cpu ? "2" : "8", "--warmup", cpu ? "1" : "3",
      "--reference-spp", cpu ? "4" : "16", "--no-charts"};
  std::vector<ThesisSweep> sweeps = {
      {o.outDir + "/thesis-keys", size, {"--strategies", "fixed,origin-direction,average"}},
      // Section 4.3: "the distribution resets when the variance exceeds 20", on the camera-clamped grid.
      {o.outDir + "/thesis-gaussian", size, {"--strategies", "gaussian", "--gauss-resets", "20", "--clamps", "50"}},
  };
  for (ThesisSweep& s : sweeps) {
    s.benchArgs.insert(s.benchArgs.begin(), common.begin(), common.end());
    s.benchArgs.insert(s.benchArgs.end(), {"--out-dir", s.folder});
    if (!o.rounds.empty()) s.benchArgs.insert(s.benchArgs.end(), {"--rounds", o.rounds});
    if (!o.device.empty()) s.benchArgs.insert(s.benchArgs.end(), {"--device", o.device});
    s.benchArgs.insert(s.benchArgs.end(), o.passOn.begin(), o.passOn.end());
  }
  return sweeps;
}

int runThesisStudy(const StudyOptions& o, bool cpu) {
  std::vector<ThesisSweep> sweeps;
  try {
    sweeps = thesisPlan(o, cpu);
  } catch (const UsageError& e) {
    std::fprintf(stderr, "raylab study: %s\n", e.what());
    return kExitUsage;
  }
  std::error_code ec;
  std::filesystem::create_directories(o.outDir, ec);
  if (ec) {
    std::fprintf(stderr, "raylab study: cannot make %s: %s\n", o.outDir.c_str(), ec.message().c_str());
    return kExitFailure;
  }
  std::vector<std::string> args = {"--out", o.outDir + "/thesis"};
  const std::string& size = sweeps.front().size;
  if (size != "2048x1024" || cpu)
    args.insert(args.end(), {"--note", std::string("Measured ") + (cpu ? "on a CPU device " : "") + "at " + size +
                                           ", not the thesis's 2048x1024 on its RTX GPU."});
  for (size_t i = 0; i < sweeps.size(); ++i) {
    std::fprintf(stderr, "raylab study: --thesis sweep %zu of %zu (%s)\n", i + 1, sweeps.size(), sweeps[i].folder.c_str());
    if (const int rc = runBenchCommand(sweeps[i].benchArgs); rc != kExitOk) {
      std::fprintf(stderr, "raylab study: the bench of %s exited %d\n", sweeps[i].folder.c_str(), rc);
      return rc;
    }
    args.push_back(sweeps[i].folder);
  }
  const ChartsOutcome table = runLabScript("study/thesis_table.py", args);
  if (table.kind == ChartsOutcome::Kind::Drawn) {
    std::printf("study: the thesis's table in %s/thesis.md and %s/thesis.html\n", o.outDir.c_str(), o.outDir.c_str());
    return kExitOk;
  }
  std::fprintf(stderr, "raylab study: no thesis table: %s; the results are in %s\n", table.why.c_str(), o.outDir.c_str());
  return table.kind == ChartsOutcome::Kind::Unavailable ? kExitOk : kExitFailure;
}

}  // namespace raylab
