#include "app/study/study_command.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>

#include <nlohmann/json.hpp>

#include "app/bench/bench_command.h"
#include "app/bench/bench_merge.h"
#include "app/bench/bench_sweep.h"
#include "app/bench/bench_charts_run.h"
#include "app/cli_options.h"
#include "app/bench/case_views.h"
#include "app/command_errors.h"
#include "app/scene_setup.h"
#include "app/study/study_plan.h"
#include "app/study/study_thesis.h"
#include "renderer/checked_write.h"
#include "renderer/git_revision.h"
#include "renderer/vk/vk_context.h"

namespace raylab {
namespace {

// The help: what --quick changes is made from the presets (app/study/study_plan.cpp), not written here again.
std::string studyHelp() {
  return
    "usage: raylab study SCENE[@VIEW] [--quick] [--out-dir DIR] [--sizes WxH,...] [--bounces N,...]\n"
    "                    [--strategies a,b,...] [--rounds N] [--device NAME|N] [--validate[=sync|gpu-av]]\n"
    "                    [--shard i/K] [--camera-path FILE|builtin:NAME | --no-motion]\n"
    "       raylab study temple --thesis [--out-dir DIR] [--rounds N] [--device NAME|N]\n"
    "       raylab study --merge DIR... [--out-dir OUT]\n"
    "  --out-dir DIR       where the study goes (default study-out, in the current folder)\n"
    "Where sorting pays on one scene: one `raylab bench` sweep per image size (paths per frame from 131k to\n"
    "8.4M), the strategies with the always and auto policies, the megakernel and the unsorted wavefront (split\n"
    "and fused) as baselines; then one HTML report\n"
    "(DIR/report.html, charts embedded) from app/study/study_report.py. The presets (a CPU device gets sizes it renders\n"
    "in minutes; --quick fewer sizes, bounces and strategies; the report's top says which ran):\n"
    "  GPU:          " + presetText(studyPreset(false, false)) + "\n"
    "  CPU:          " + presetText(studyPreset(false, true)) + "\n"
    "  --quick, GPU: " + presetText(studyPreset(true, false)) + "\n"
    "  --quick, CPU: " + presetText(studyPreset(true, true)) + "\n"
    "Every cell is measured in interleaved rounds (raylab bench --rounds); the report's times are medians over the\n"
    "rounds with their spread, and it says where a difference is within the spread. The auto policy is timed\n"
    "once its plan stops exploring.\n"
    "SCENE is any --scene value (temple, a .gltf path, ...). Each size's results stay in\n"
    "DIR/size-WxH/ (results.csv, results.jsonl): a size that is killed continues with\n"
    "`raylab bench --resume DIR/size-WxH`; DIR/study.json records the study.\n"
    "  --rounds N          rounds per cell, 1.." + std::to_string(kMaxRounds) + " (default: the preset's)\n"
    "  --shard i/K         run only the study's cells g (0-based: the sizes in order, each size's bench cells\n"
    "                      in plan order) with g mod K = i, 0 <= i < K: one of K disjoint parts, for K GPUs\n"
    "                      or hosts (every shard with the same flags but --out-dir and --device); writes the\n"
    "                      results but no report\n"
    "  --camera-path FILE|builtin:NAME  the camera path of the motion section (default: every built-in path of\n"
    "                      the scene, `raylab bench --camera-path builtin:list`): after the sizes, one\n"
    "                      `raylab bench --camera-path` per path at the largest size of at most\n"
    "                      " + std::to_string(kMotionMaxPaths) + " paths per frame and the first bounce count: the\n"
    "                      strategies under always and auto against the unsorted wavefront (never) and\n"
    "                      the megakernel, in DIR/motion-NAME/; the report's \"Under a\n"
    "                      moving camera\" tables each from its motion.json. The presets cut a path to its\n"
    "                      first frames (above); a sharded study measures no path\n"
    "  --no-motion         no camera path: the still views only\n"
    "  --thesis            the source study's Tables 4.1-4.2 and section 4.3 re-measured: temple alley, hall and\n"
    "                      openings at 2048x1024 (256x128 on a CPU device; one --sizes value replaces it),\n"
    "                      4 bounces; unsorted, fixed, origin-direction, average, and gaussian reset at 20 on\n"
    "                      a camera-clamped grid; bitonic and radix. DIR/thesis.md and thesis.html put each\n"
    "                      figure beside the thesis's, both as ratios to their own unsorted path tracer, and\n"
    "                      say which of its findings hold\n"
    "  --merge DIR...      put the K shard folders of one study back together in OUT (default study-out):\n"
    "                      each size with `raylab bench --merge`, then the report; refuses folders of other\n"
    "                      studies, a shard missing or given twice (exit 2)\n";
}

StudyOptions parseStudyOptions(const std::vector<std::string>& args) {
  StudyOptions o;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&]() -> const std::string& {
      if (i + 1 >= args.size()) throw UsageError(a + " needs a value");
      return args[++i];
    };
    if (a == "--quick") o.quick = true;
    else if (a == "--thesis") o.thesis = true;
    else if (a == "--out-dir") o.outDir = value();
    else if (a == "--sizes") o.sizes = splitList(value());
    else if (a == "--bounces") o.bounces = value();
    else if (a == "--strategies") o.strategies = value();
    else if (a == "--rounds") o.rounds = std::to_string(parseUint(a, value(), 1, kMaxRounds));
    else if (a == "--device") o.device = value();
    else if (a == "--shard") o.shard = parseShard(value());
    else if (a == "--camera-path") o.cameraPath = value();
    else if (a == "--no-motion") o.noMotion = true;
    else if (a == "--validate" || a.rfind("--validate=", 0) == 0) o.passOn.push_back(a);
    else if (a.rfind("--", 0) == 0)
      throw UsageError(unknownOptionMessage(a, {"--quick", "--thesis", "--out-dir", "--sizes", "--bounces", "--strategies",
                                                "--device", "--shard", "--validate", "--merge",
                                                "--camera-path", "--no-motion"}));
    else if (o.target.empty()) o.target = a;
    else throw UsageError("one scene per study, got '" + o.target + "' and '" + a + "'");
  }
  if (o.target.empty()) throw UsageError("which scene? raylab study SCENE[@VIEW]");
  if (o.outDir.empty()) throw UsageError("--out-dir needs a folder");
  if (o.noMotion && !o.cameraPath.empty()) throw UsageError("--camera-path and --no-motion: give one of them");
  if (o.thesis && !o.cameraPath.empty()) throw UsageError("--thesis re-measures still views: --camera-path does not apply");
  for (const std::string& size : o.sizes) parseCommonOptions({"--size", size});  // --size's rules, said at once
  if (const size_t at = o.target.rfind('@'); at != std::string::npos)  // a bad view is exit 2 before any sweep
    checkCaseView(o.target.substr(0, at), o.target.substr(at + 1));
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

// DIR/study.json: what `raylab study --merge` needs of a study folder (its sizes, the report's note, which
// shard it is); the cells themselves are in each size's sweep.json.
struct StudyRecord {
  std::string target, note, gitRevision;
  std::vector<std::string> sizes;
  BenchShard shard;
};

void writeStudyRecord(const std::string& dir, const StudyRecord& r) {
  const nlohmann::json j = {{"target", r.target}, {"sizes", r.sizes}, {"note", r.note},
                            {"git_revision", r.gitRevision}, {"shard", r.shard.text()}};
  writeFileChecked(dir + "/study.json", j.dump(1) + "\n");
}

StudyRecord readStudyRecord(const std::string& dir) {
  std::ifstream in(dir + "/study.json");
  if (!in) throw UsageError(dir + ": no study.json there (not a raylab study folder)");
  try {
    const nlohmann::json j = nlohmann::json::parse(in);
    return {j.at("target").get<std::string>(), j.at("note").get<std::string>(), j.at("git_revision").get<std::string>(),
            j.at("sizes").get<std::vector<std::string>>(), parseShard(j.at("shard").get<std::string>())};
  } catch (const UsageError& e) {
    throw UsageError(dir + ": study.json is damaged (" + e.what() + ")");
  } catch (const nlohmann::json::exception& e) {
    throw UsageError(dir + ": study.json is damaged (" + e.what() + ")");
  }
}

// The report from every size's folder; a missing Python or matplotlib leaves the results and says how to
// make the report elsewhere.
// `motion`: the motion sweeps' folders; `motionNote`: why there are none (the report says it in their place).
int makeReport(const std::string& outDir, const std::vector<std::string>& folders, const std::string& note,
               const std::vector<std::string>& motion, const std::string& motionNote) {
  const std::string out = outDir + "/report.html";
  std::vector<std::string> args;
  if (!note.empty()) args = {"--note", note};
  for (const std::string& m : motion) args.insert(args.end(), {"--motion", m});
  if (!motionNote.empty()) args.insert(args.end(), {"--motion-note", motionNote});
  args.push_back(out);
  args.insert(args.end(), folders.begin(), folders.end());
  const ChartsOutcome report = runLabScript("study/study_report.py", args);
  std::string command = "python3 " + labScript("study/study_report.py");
  for (const std::string& a : args) command += " '" + a + "'";
  switch (report.kind) {
    case ChartsOutcome::Kind::Drawn:
      std::printf("study: report in %s\n", out.c_str());
      return kExitOk;
    case ChartsOutcome::Kind::Unavailable:
      std::fprintf(stderr, "raylab study: no report: %s; the results are in %s; make it where matplotlib is with:\n  %s\n",
                   report.why.c_str(), outDir.c_str(), command.c_str());
      return kExitOk;
    case ChartsOutcome::Kind::Failed:
      break;
  }
  std::fprintf(stderr, "raylab study: the report failed: %s; the results are in %s\n", report.why.c_str(), outDir.c_str());
  return kExitFailure;
}

// `raylab study --merge DIR... [--out-dir OUT]`: the study-level checks first (one study, every shard once),
// then each size's shards through `raylab bench --merge` (which refuses other sweeps, revisions and unfinished
// shards), then the report.
int runStudyMerge(const std::vector<std::string>& args) {
  std::vector<std::string> dirs;
  std::string outDir = "study-out";
  std::vector<StudyRecord> records;
  try {
    for (size_t i = 0; i < args.size(); ++i) {
      if (args[i] == "--merge") {
        while (i + 1 < args.size() && args[i + 1].rfind("--", 0) != 0) dirs.push_back(args[++i]);
      } else if (args[i] == "--out-dir") {
        if (i + 1 >= args.size() || args[i + 1].empty()) throw UsageError("--out-dir needs a folder");
        outDir = args[++i];
      } else {
        throw UsageError("--merge takes shard folders and --out-dir only, not '" + args[i] +
                         "' (the study is the one the folders recorded)");
      }
    }
    if (dirs.empty()) throw UsageError("--merge needs the shard folders of a study (e.g. --merge s0 s1 s2)");
    std::error_code ec;
    for (const std::string& d : dirs)
      if (std::filesystem::equivalent(d, outDir, ec))
        throw UsageError("--merge: --out-dir " + outDir + " is one of the shard folders; name a new folder");
    std::map<uint32_t, std::string> byIndex;
    for (const std::string& d : dirs) {
      records.push_back(readStudyRecord(d));
      const StudyRecord &r = records.back(), &first = records.front();
      if (r.target != first.target || r.sizes != first.sizes || r.note != first.note)
        throw UsageError(d + " holds a different study from " + dirs.front() + " (their study.json differ)");
      if (r.shard.count != first.shard.count)
        throw UsageError(d + " is shard " + r.shard.text() + " and " + dirs.front() + " shard " + first.shard.text() +
                         ": shards of one split have one K");
      if (!byIndex.emplace(r.shard.index, d).second)
        throw UsageError("shard " + r.shard.text() + " is given twice (" + byIndex[r.shard.index] + " and " + d + ")");
    }
    for (uint32_t i = 0; i < records.front().shard.count; ++i)
      if (!byIndex.count(i))
        throw UsageError("shard " + std::to_string(i) + "/" + std::to_string(records.front().shard.count) +
                         " is missing: merge all " + std::to_string(records.front().shard.count) + " shards of the study");
  } catch (const UsageError& e) {
    std::fprintf(stderr, "raylab study: --merge: %s\n", e.what());
    return kExitUsage;
  }
  const StudyRecord& study = records.front();
  std::vector<std::string> folders;
  for (const std::string& size : study.sizes) {
    std::vector<std::string> merge{"--merge"};
    for (const std::string& d : dirs) merge.push_back(d + "/size-" + size);
    const std::string folder = outDir + "/size-" + size;
    merge.insert(merge.end(), {"--out-dir", folder, "--no-charts"});
    if (const int rc = runBenchMerge(merge); rc != kExitOk) {
      std::fprintf(stderr, "raylab study: --merge: size %s did not merge (exit %d)%s\n", size.c_str(), rc,
                   folders.empty() ? "" : "; the sizes before it are merged in the out folder");
      return rc;
    }
    folders.push_back(folder);
  }
  try {
    StudyRecord whole = study;
    whole.shard = BenchShard{};
    writeStudyRecord(outDir, whole);
  } catch (const WriteError& e) {
    std::fprintf(stderr, "raylab study: --merge: %s\n", e.what());
    return kExitFailure;
  }
  std::printf("study: merged %zu shards of %zu sizes into %s\n", dirs.size(), study.sizes.size(), outDir.c_str());
  std::fflush(stdout);
  return makeReport(outDir, folders, study.note, {}, kShardedMotionNote);
}

}  // namespace

int runStudyCommand(const std::vector<std::string>& args) {
  if (!args.empty() && (args[0] == "--help" || args[0] == "-h")) {
    std::printf("%s", studyHelp().c_str());
    return kExitOk;
  }
  if (std::find(args.begin(), args.end(), "--merge") != args.end()) return runStudyMerge(args);
  StudyOptions o;
  std::vector<StudySize> plan;
  std::vector<StudyMotion> motion;
  std::string motionNote;  // why the report has no motion sweeps, where it has none
  bool cpu = false;
  std::string note;
  try {
    o = parseStudyOptions(args);
    cpu = isCpuDevice(o);
    if (o.thesis) return runThesisStudy(o, cpu);
    const StudyPreset preset = studyPreset(o.quick, cpu);
    plan = studyPlan(o, preset);
    const std::vector<std::string> paths = o.noMotion ? std::vector<std::string>{} : studyMotionPaths(o);
    motion = studyMotionPlan(o, preset, paths);
    if (o.noMotion) motionNote = "left out (--no-motion)";
    else if (!o.shard.whole()) motionNote = kShardedMotionNote;
    else if (paths.empty()) motionNote = o.target + " has no built-in camera path: give one with --camera-path FILE";
    if (cpu && o.sizes.empty())
      note = "Measured on a CPU device: the sizes are ones it renders in minutes (up to " + plan.back().size +
             "), far below where sorting pays on a GPU.";
    if (o.quick) note += (note.empty() ? "" : " ") + quickText(cpu) + ".";
  } catch (const UsageError& e) {
    printUsageError("raylab study", e.what());
    return kExitUsage;
  }
  if (!note.empty()) std::fprintf(stderr, "raylab study: %s\n", note.c_str());
  std::vector<std::string> sizes;
  for (const StudySize& s : plan) sizes.push_back(s.size);
  try {
    std::filesystem::create_directories(o.outDir);
    writeStudyRecord(o.outDir, StudyRecord{o.target, note, gitRevision(), sizes, o.shard});
  } catch (const WriteError& e) {
    std::fprintf(stderr, "raylab study: %s\n", e.what());
    return kExitFailure;
  }

  // A size's time grows with its paths and its cells: what is left, at the rate measured so far.
  uint64_t totalWork = 0, doneWork = 0;
  size_t studyCells = 0, shardCells = 0;
  for (const StudySize& s : plan) {
    totalWork += pathsOf(s.size) * s.shardCells();
    studyCells += s.cells;
    shardCells += s.shardCells();
  }
  if (!o.shard.whole())
    std::fprintf(stderr, "raylab study: shard %s: %zu of the study's %zu cells\n", o.shard.text().c_str(), shardCells,
                 studyCells);
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::string> folders;
  for (size_t i = 0; i < plan.size(); ++i) {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::string left = doneWork ? " about " + std::to_string(int(elapsed / doneWork * (totalWork - doneWork))) + " s left" : "";
    std::fprintf(stderr, "raylab study: size %s (%zu of %zu, %zu done), %.0f s so far,%s\n", plan[i].size.c_str(), i + 1,
                 plan.size(), i, elapsed, left.empty() ? " time left unknown yet" : left.c_str());
    const int rc = runBenchCommand(plan[i].benchArgs);
    if (rc != kExitOk) {
      std::fprintf(stderr, "raylab study: the bench of size %s exited %d; the sizes done so far are in %s\n",
                   plan[i].size.c_str(), rc, o.outDir.c_str());
      return rc;
    }
    folders.push_back(plan[i].folder);
    doneWork += pathsOf(plan[i].size) * plan[i].shardCells();
  }
  if (!motionNote.empty()) std::fprintf(stderr, "raylab study: %s\n", motionNote.c_str());
  std::vector<std::string> motionFolders;
  for (size_t i = 0; i < motion.size(); ++i) {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::fprintf(stderr, "raylab study: camera path %s (%zu of %zu), %.0f s so far\n", motion[i].path.c_str(), i + 1,
                 motion.size(), elapsed);
    if (const int rc = runBenchCommand(motion[i].benchArgs); rc != kExitOk) {
      std::fprintf(stderr, "raylab study: the bench along %s exited %d; the sizes and paths done so far are in %s\n",
                   motion[i].path.c_str(), rc, o.outDir.c_str());
      return rc;
    }
    motionFolders.push_back(motion[i].folder);
  }
  if (!o.shard.whole()) {
    std::printf("study: shard %s done, results in %s; no report from one shard: once all %u shards are done,\n"
                "  raylab study --merge DIR... --out-dir OUT\n"
                "with DIR... the %u shards' --out-dir folders (this one is %s) makes OUT and its report\n",
                o.shard.text().c_str(), o.outDir.c_str(), o.shard.count, o.shard.count, o.outDir.c_str());
    return kExitOk;
  }
  // The report names the study's own command and how long it measured (issue 38).
  std::string command = "raylab study";
  for (const std::string& a : args) command += " " + a;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  char took[96];
  std::snprintf(took, sizeof(took), " Measured in %.0f s.", seconds);
  return makeReport(o.outDir, folders, (note.empty() ? "" : note + " ") + "Command: " + command + "." + took,
                    motionFolders, motionNote);
}

}  // namespace raylab
