#include "app/study_command.h"

#include <chrono>
#include <cstdio>
#include <filesystem>

#include "app/bench_command.h"
#include "app/bench_sweep.h"
#include "app/bench_charts_run.h"
#include "app/cli_options.h"
#include "app/command_errors.h"
#include "app/scene_setup.h"
#include "renderer/vk/vk_context.h"

namespace raylab {
namespace {

// The standard study (issue 22): the path count from 1.3e5 to 8.4e6 (image sizes at 1 sample per frame), the
// strategies that differ in kind (dead-last, fixed, two-point and a learned length), the policies, and the
// baselines bench always measures (megakernel, the unsorted wavefront; split and fused). --quick keeps two
// strategies, one bounce count and three sizes; a CPU device gets sizes it can do in minutes.
struct StudyPreset {
  std::vector<std::string> sizes;
  std::string bounces, strategies, timedFrames, warmup;
};

StudyPreset presetFor(bool quick, bool cpu) {
  if (cpu)
    return quick ? StudyPreset{{"128x64", "256x128"}, "4", "two-point", "2", "1"}
                 : StudyPreset{{"128x64", "256x128", "512x256"}, "4", "fixed,two-point", "3", "1"};
  if (quick) return {{"512x256", "2048x1024", "4096x2048"}, "4", "fixed,two-point", "6", "3"};
  return {{"512x256", "1024x512", "2048x1024", "4096x2048"}, "4,8", "dead-last,fixed,two-point,average", "8", "4"};
}

struct StudyOptions {
  std::string target;  // SCENE[@VIEW]
  std::string outDir = "study-out";
  bool quick = false;
  std::vector<std::string> sizes;   // --sizes: the preset's otherwise
  std::string bounces, strategies;  // --bounces, --strategies: the preset's otherwise
  std::string device;
  std::vector<std::string> passOn;  // --validate flags, given to every bench run
};

const char* kStudyHelp =
    "usage: raylab study SCENE[@VIEW] [--quick] [--out-dir DIR] [--sizes WxH,...] [--bounces N,...]\n"
    "                    [--strategies a,b,...] [--device NAME] [--validate[=sync|gpu-av]]\n"
    "Where sorting pays on one scene: one `raylab bench` sweep per image size (paths per frame from 131k to\n"
    "8.4M), 4 and 8 bounces, the strategies dead-last, fixed, two-point and average with the always and auto\n"
    "policies, the megakernel and the unsorted wavefront (split and fused) as baselines; then one HTML report\n"
    "(DIR/report.html, charts embedded) from app/study_report.py. --quick: sizes 512x256, 2048x1024 and\n"
    "4096x2048, 4 bounces, fixed and two-point. On a CPU device the sizes shrink to what it can do (the report\n"
    "says so). SCENE is any --scene value (temple, a .gltf path, ...). Each size's results stay in\n"
    "DIR/size-WxH/ (results.csv, results.jsonl): a size that is killed continues with\n"
    "`raylab bench --resume DIR/size-WxH`.\n";

StudyOptions parseStudyOptions(const std::vector<std::string>& args) {
  StudyOptions o;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&]() -> const std::string& {
      if (i + 1 >= args.size()) throw UsageError(a + " needs a value");
      return args[++i];
    };
    if (a == "--quick") o.quick = true;
    else if (a == "--out-dir") o.outDir = value();
    else if (a == "--sizes") o.sizes = splitList(value());
    else if (a == "--bounces") o.bounces = value();
    else if (a == "--strategies") o.strategies = value();
    else if (a == "--device") o.device = value();
    else if (a == "--validate" || a.rfind("--validate=", 0) == 0) o.passOn.push_back(a);
    else if (a.rfind("--", 0) == 0) throw UsageError("unknown option '" + a + "'");
    else if (o.target.empty()) o.target = a;
    else throw UsageError("one scene per study, got '" + o.target + "' and '" + a + "'");
  }
  if (o.target.empty()) throw UsageError("which scene? raylab study SCENE[@VIEW]");
  if (o.outDir.empty()) throw UsageError("--out-dir needs a folder");
  for (const std::string& size : o.sizes) parseCommonOptions({"--size", size});  // --size's rules, said at once
  return o;
}

bool isCpuDevice(const StudyOptions& o) {
  ContextOptions c;
  c.deviceName = o.device;
  c.quiet = true;
  return VulkanContext(c).info().isCpu;
}

uint64_t pathsOf(const std::string& size) {
  Settings s = parseCommonOptions({"--size", size}).settings;
  return uint64_t(s.width) * s.height * s.sppPerFrame;
}

// One bench sweep of the study at one image size.
std::vector<std::string> benchArgs(const StudyOptions& o, const StudyPreset& p, const std::string& size) {
  std::vector<std::string> a{"--cases", o.target, "--size", size, "--bounces", o.bounces.empty() ? p.bounces : o.bounces,
                             "--strategies", o.strategies.empty() ? p.strategies : o.strategies,
                             "--sort-policies", "always,auto", "--trace-shades", "split,fused",
                             "--timed-frames", p.timedFrames, "--warmup", p.warmup, "--reference-spp", "16",
                             "--no-charts",  // the report draws its own
                             "--out-dir", o.outDir + "/size-" + size};
  if (!o.device.empty()) a.insert(a.end(), {"--device", o.device});
  a.insert(a.end(), o.passOn.begin(), o.passOn.end());
  return a;
}

// The report from every size's folder; a missing Python or matplotlib leaves the results and says how to
// make the report elsewhere.
int makeReport(const StudyOptions& o, const std::vector<std::string>& folders, const std::string& note) {
  const std::string out = o.outDir + "/report.html";
  std::vector<std::string> args;
  if (!note.empty()) args = {"--note", note};
  args.push_back(out);
  args.insert(args.end(), folders.begin(), folders.end());
  const ChartsOutcome report = runLabScript("study_report.py", args);
  std::string command = "python3 " + labScript("study_report.py");
  for (const std::string& a : args) command += " '" + a + "'";
  switch (report.kind) {
    case ChartsOutcome::Kind::Drawn:
      std::printf("study: report in %s\n", out.c_str());
      return kExitOk;
    case ChartsOutcome::Kind::Unavailable:
      std::fprintf(stderr, "raylab study: no report: %s; the results are in %s; make it where matplotlib is with:\n  %s\n",
                   report.why.c_str(), o.outDir.c_str(), command.c_str());
      return kExitOk;
    case ChartsOutcome::Kind::Failed:
      break;
  }
  std::fprintf(stderr, "raylab study: the report failed: %s; the results are in %s\n", report.why.c_str(), o.outDir.c_str());
  return kExitFailure;
}

}  // namespace

int runStudyCommand(const std::vector<std::string>& args) {
  if (!args.empty() && (args[0] == "--help" || args[0] == "-h")) {
    std::printf("%s", kStudyHelp);
    return kExitOk;
  }
  StudyOptions o;
  try {
    o = parseStudyOptions(args);
  } catch (const UsageError& e) {
    std::fprintf(stderr, "raylab study: %s\n\n%s", e.what(), kStudyHelp);
    return kExitUsage;
  }
  const bool cpu = isCpuDevice(o);
  const StudyPreset preset = presetFor(o.quick, cpu);
  const std::vector<std::string> sizes = o.sizes.empty() ? preset.sizes : o.sizes;
  const std::string note = cpu && o.sizes.empty()
                               ? "Measured on a CPU device: the sizes are ones it renders in minutes (up to " +
                                     sizes.back() + "), far below where sorting pays on a GPU."
                               : "";
  if (!note.empty()) std::fprintf(stderr, "raylab study: %s\n", note.c_str());
  std::filesystem::create_directories(o.outDir);

  uint64_t totalPaths = 0, donePaths = 0;
  for (const std::string& size : sizes) totalPaths += pathsOf(size);
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::string> folders;
  for (size_t i = 0; i < sizes.size(); ++i) {
    // A size's time grows with its paths: what is left, at the rate measured so far.
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::string left = donePaths ? " about " + std::to_string(int(elapsed / donePaths * (totalPaths - donePaths))) + " s left" : "";
    std::fprintf(stderr, "raylab study: size %s (%zu of %zu, %zu done), %.0f s so far,%s\n", sizes[i].c_str(), i + 1,
                 sizes.size(), i, elapsed, left.empty() ? " time left unknown yet" : left.c_str());
    const int rc = runBenchCommand(benchArgs(o, preset, sizes[i]));
    if (rc != kExitOk) {
      std::fprintf(stderr, "raylab study: the bench of size %s exited %d; the sizes done so far are in %s\n", sizes[i].c_str(),
                   rc, o.outDir.c_str());
      return rc;
    }
    folders.push_back(o.outDir + "/size-" + sizes[i]);
    donePaths += pathsOf(sizes[i]);
  }
  return makeReport(o, folders, note);
}

}  // namespace raylab
