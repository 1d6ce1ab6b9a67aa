#include "app/study/study_plan.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "app/bench/bench_sweep.h"
#include "app/bench/case_views.h"
#include "app/cli_options.h"

namespace raylab {

// Paths per frame from 1.3e5 to 8.4e6 (image sizes at 1 sample per frame), the strategies that differ in kind
// (dead-last, fixed, two-point and a learned length), the policies, and the baselines bench always measures
// (megakernel, the unsorted wavefront; split and fused). --quick keeps two strategies, one bounce count and
// three sizes; a CPU device gets sizes it can do in minutes.
// Every preset measures each cell in 3 interleaved rounds (issue 34): two identical lavapipe studies of one
// round disagreed on the best policy and on whether sorting beat the megakernel.
// The motion sweeps replay a path's first pathFrames frames: --quick and a CPU device keep the built-in
// paths' first cut (at frame 30) and the frames after it, where the recovery is measured; the full GPU study
// replays the whole path.
StudyPreset studyPreset(bool quick, bool cpu) {
  if (cpu)
    return quick ? StudyPreset{{"128x64", "256x128"}, "4", "two-point", "2", "1", "3", "40"}
                 : StudyPreset{{"128x64", "256x128", "512x256"}, "4", "fixed,two-point", "3", "1", "3", "60"};
  if (quick) return {{"512x256", "2048x1024", "4096x2048"}, "4", "fixed,two-point", "6", "3", "3", "60"};
  return {{"512x256", "1024x512", "2048x1024", "4096x2048"}, "4,8", "dead-last,fixed,two-point,average", "8", "4", "3", ""};
}

namespace {
std::string joined(const std::vector<std::string>& items) {
  std::string text;
  for (const std::string& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}
}  // namespace

std::string presetText(const StudyPreset& p) {
  return "sizes " + joined(p.sizes) + "; " + joined(splitList(p.bounces)) + " bounces; " +
         joined(splitList(p.strategies)) + "; " + p.timedFrames + " timed frames after " + p.warmup + " warm-up; " +
         p.rounds + " rounds; camera paths " + (p.pathFrames.empty() ? "whole" : "cut to " + p.pathFrames + " frames");
}

std::string quickText(bool cpu) {
  const StudyPreset quick = studyPreset(true, cpu), full = studyPreset(false, cpu);
  const std::vector<std::string> kept = splitList(quick.strategies);
  std::vector<std::string> dropped;
  for (const std::string& s : splitList(full.strategies))
    if (std::find(kept.begin(), kept.end(), s) == kept.end()) dropped.push_back(s);
  return std::string("--quick on a ") + (cpu ? "CPU" : "GPU") + " device: " + presetText(quick) + " (the full study: " +
         presetText(full) + ")" + (dropped.empty() ? "" : "; it drops the strategies " + joined(dropped));
}

size_t StudySize::shardCells() const {
  size_t n = 0;
  for (size_t c = 0; c < cells; ++c) n += benchShard.contains(c);
  return n;
}

std::vector<StudySize> studyPlan(const StudyOptions& o, const StudyPreset& p) {
  const std::vector<std::string>& sizes = o.sizes.empty() ? p.sizes : o.sizes;
  std::vector<StudySize> plan;
  size_t first = 0;
  for (const std::string& size : sizes) {
    StudySize s;
    s.size = size;
    s.folder = o.outDir + "/size-" + size;
    s.benchArgs = {"--cases", o.target, "--size", size, "--bounces", o.bounces.empty() ? p.bounces : o.bounces,
                   "--strategies", o.strategies.empty() ? p.strategies : o.strategies,
                   "--sort-policies", "always,auto", "--trace-shades", "split,fused",
                   "--timed-frames", p.timedFrames, "--warmup", p.warmup, "--reference-spp", "16",
                   "--rounds", o.rounds.empty() ? p.rounds : o.rounds,
                   "--no-charts",  // the report draws its own
                   "--out-dir", s.folder};
    if (!o.device.empty()) s.benchArgs.insert(s.benchArgs.end(), {"--device", o.device});
    s.benchArgs.insert(s.benchArgs.end(), o.passOn.begin(), o.passOn.end());
    s.cells = parseBenchPlan(s.benchArgs).cells.size();
    s.firstCell = first;
    first += s.cells;
    const uint32_t k = o.shard.count;
    s.benchShard = BenchShard{static_cast<uint32_t>((o.shard.index + k - s.firstCell % k) % k), k};
    if (!o.shard.whole()) s.benchArgs.insert(s.benchArgs.end(), {"--shard", s.benchShard.text()});
    plan.push_back(std::move(s));
  }
  return plan;
}

namespace {

std::string sceneOf(const std::string& target) { return target.substr(0, target.rfind('@')); }

uint64_t pathsPerFrame(const std::string& size) {
  const Settings s = parseCommonOptions({"--size", size}).settings;
  return uint64_t(s.width) * s.height * s.sppPerFrame;
}

// "builtin:cut" -> "cut", "paths/my walk.json" -> "my-walk": a folder name.
std::string pathFolderName(const std::string& spec) {
  std::string name = spec.rfind("builtin:", 0) == 0 ? spec.substr(8) : std::filesystem::path(spec).stem().string();
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '_' && c != '-') c = '-';
  return name.empty() ? "path" : name;
}

}  // namespace

std::vector<std::string> studyMotionPaths(const StudyOptions& o) {
  const std::string scene = sceneOf(o.target);
  if (o.cameraPath.empty()) return caseBuiltinPaths(scene);
  checkCasePath(scene, o.cameraPath);  // a missing file or unknown built-in: exit 2 before anything renders
  return {o.cameraPath};
}

std::vector<StudyMotion> studyMotionPlan(const StudyOptions& o, const StudyPreset& p, const std::vector<std::string>& paths) {
  if (o.noMotion || !o.shard.whole()) return {};
  const std::vector<std::string>& sizes = o.sizes.empty() ? p.sizes : o.sizes;
  std::string fit, smallest;  // the largest size up to kMotionMaxPaths; where every size is larger, the smallest
  for (const std::string& s : sizes) {
    const uint64_t n = pathsPerFrame(s);
    if (n <= kMotionMaxPaths && (fit.empty() || n > pathsPerFrame(fit))) fit = s;
    if (smallest.empty() || n < pathsPerFrame(smallest)) smallest = s;
  }
  const std::string size = fit.empty() ? smallest : fit;
  std::vector<StudyMotion> plan;
  for (const std::string& path : paths) {
    StudyMotion m;
    m.path = path;
    m.folder = o.outDir + "/motion-" + pathFolderName(path);
    // The cases are the scene alone: a path sets every frame's camera, so bench refuses a view beside it.
    m.benchArgs = {"--cases", sceneOf(o.target), "--camera-path", path, "--size", size,
                   "--bounces", splitList(o.bounces.empty() ? p.bounces : o.bounces).front(),
                   "--strategies", o.strategies.empty() ? p.strategies : o.strategies,
                   "--sort-policies", "always,auto", "--warmup", p.warmup,
                   "--rounds", o.rounds.empty() ? p.rounds : o.rounds,
                   "--no-charts",  // the report draws the path charts it links
                   "--out-dir", m.folder};
    if (!p.pathFrames.empty()) m.benchArgs.insert(m.benchArgs.end(), {"--frames", p.pathFrames});
    if (!o.device.empty()) m.benchArgs.insert(m.benchArgs.end(), {"--device", o.device});
    m.benchArgs.insert(m.benchArgs.end(), o.passOn.begin(), o.passOn.end());
    parseBenchPlan(m.benchArgs);  // what bench would refuse, refused now
    plan.push_back(std::move(m));
  }
  return plan;
}

}  // namespace raylab
