#include "app/bench_sweep.h"

#include "app/setting_flags.h"
#include "renderer/reorder/key_functions.h"
#include "renderer/reorder/key_strategies.h"
#include "scenes/scene_library.h"
#include "scenes/temple_detail.h"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace raylab {

std::vector<std::string> splitList(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream ss(text);
  for (std::string item; std::getline(ss, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

namespace {

// Reads `name = value` lines (# comments) into flag/value pairs.
std::vector<std::string> readSweepFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw UsageError("--sweep: cannot read " + path);
  std::vector<std::string> args;
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    line = line.substr(0, line.find('#'));
    size_t eq = line.find('=');
    auto trim = [](std::string s) {
      size_t a = s.find_first_not_of(" \t"), b = s.find_last_not_of(" \t\r");
      return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
    };
    if (trim(line).empty()) continue;
    if (eq == std::string::npos) throw UsageError(path + ":" + std::to_string(n) + ": expected name = value");
    args.push_back("--" + trim(line.substr(0, eq)));
    args.push_back(trim(line.substr(eq + 1)));
  }
  return args;
}

struct Axes {
  std::vector<std::string> strategies{"all"}, sorts{"radix"}, grids{"auto"}, clamps{"off"}, resets{}, factors{};
  std::vector<std::string> tracers{}, sers{}, serHints{"two-point"};
  std::vector<std::string> bvhs{};        // --bvhs: empty keeps the render flag's (binary); compute tracer only
  std::vector<std::string> policies{"always"};
  std::vector<std::string> sortBits{};    // --sort-bits-list: empty keeps the render flag's (all bits)
  std::vector<std::string> fusions{};     // --fusions: empty keeps the render flag's (gather)
  std::vector<std::string> compactions{}; // --compactions: empty keeps the render flag's (shade)
  std::vector<std::string> traceShades{}; // --trace-shades: empty keeps the render flag's (split)
  std::vector<std::string> learnEvery{};  // --learn-every-list: strategies with a length cache only
  std::vector<std::string> bounces{};     // --bounces with a list: one group of cells per count
  std::vector<std::string> scaleTris{};   // --scale-tris: the sizes of every bare temple-detail case
  std::vector<std::string> sizes{};       // --sizes: image sizes (WxH); empty keeps --size's
  std::vector<std::string> spps{};        // --spps: samples per frame; empty keeps --spp's
};

// `raylab bench --bounces 2,4,8,16` sweeps the path length; every other mode takes one count. The list is
// taken out here and its first count left for parseCommonOptions, which checks it like any render flag.
std::vector<std::string> takeBounceList(std::vector<std::string>& args) {
  std::vector<std::string> list;
  for (size_t i = 0; i + 1 < args.size(); ++i)
    if (args[i] == "--bounces") {
      list = splitList(args[i + 1]);
      if (list.empty()) throw UsageError("--bounces needs a count or a list of counts, got '" + args[i + 1] + "'");
      args[i + 1] = list.front();
    }
  return list;
}

// A sweep axis given as a flag must name at least one value: `--sizes ,` is a mistake, not "the default".
std::vector<std::string> nonEmptyList(const std::string& flag, const std::string& value) {
  std::vector<std::string> list = splitList(value);
  if (list.empty()) throw UsageError(flag + " needs at least one value, got '" + value + "'");
  return list;
}

// The path count per frame as an axis: one settings per (--sizes, --spps) pair, size-major, each checked as
// a whole like the render flags (a size alone may pass and fail with the spp: too many paths per frame).
std::vector<Settings> pathCountGroups(const Settings& base, const Axes& axes) {
  const std::vector<std::string> sizes = axes.sizes.empty() ? std::vector<std::string>{""} : axes.sizes;
  const std::vector<std::string> spps = axes.spps.empty() ? std::vector<std::string>{""} : axes.spps;
  std::vector<Settings> out;
  for (const std::string& size : sizes)
    for (const std::string& spp : spps) {
      std::vector<std::string> flags;
      if (!size.empty()) flags.insert(flags.end(), {"--size", size});
      if (!spp.empty()) flags.insert(flags.end(), {"--spp", spp});
      try {
        out.push_back(overlaySettingFlags(base, flags));
      } catch (const UsageError& e) {
        throw UsageError(std::string(axes.sizes.empty() ? "--spps" : axes.spps.empty() ? "--sizes" : "--sizes x --spps") +
                         ": " + e.what());
      }
    }
  return out;
}

// Throws UsageError for a scene name or family size loadSceneByName would refuse, so that a bad case stops
// the plan before any case has run.
void checkCaseScene(const std::string& scene) {
  try {
    checkSceneName(scene);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--cases: ") + e.what());
  }
}

// Expands every bare temple-detail case into one case per --scale-tris size (in the given order).
std::vector<BenchCase> scaleCases(const std::vector<BenchCase>& cases, const std::vector<std::string>& sizes) {
  if (sizes.empty()) return cases;
  std::vector<BenchCase> out;
  bool scaled = false;
  for (const BenchCase& c : cases) {
    if (c.scene != kTempleDetailName) {
      out.push_back(c);
      continue;
    }
    scaled = true;
    for (const std::string& size : sizes) {
      std::string scene = std::string(kTempleDetailName) + ":" + size;
      try {
        parseTempleDetailTriangles(scene);
      } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("--scale-tris: ") + e.what());
      }
      out.push_back({scene, c.view});
    }
  }
  if (!scaled)
    throw UsageError(std::string("--scale-tris sizes the ") + kTempleDetailName + " cases, and --cases names none (e.g. " +
                     kTempleDetailName + "@hall)");
  return out;
}

// One sweep-axis value applied to a copy of the settings, with the CLI's validation ("clamp off" too).
Settings withFlag(const Settings& base, const std::string& flag, const std::string& value) {
  Settings s = base;
  applySettingFlag(s, flag.substr(2), value);
  return s;
}

std::string shortNumber(float v) {
  char text[32];
  std::snprintf(text, sizeof(text), "%g", v);
  return text;
}

bool usesGrid(KeyStrategy s) { return strategyInfo(s).usesGrid; }

// Axes multiply: a sweep file of under 1 KB listing four axes 40 times each is 2.6 million cells, which
// took minutes and gigabytes to plan before anything rendered (found by tests/fuzz). Far more cells than
// any bench could render in a day is a mistake in the sweep, said before the plan grows that far.
constexpr size_t kMaxCells = 10000;
void checkCellCount(size_t cells) {
  if (cells > kMaxCells)
    throw UsageError("the sweep expands to more than " + std::to_string(kMaxCells) +
                     " cells (cases x bounces x tracers x methods); sweep fewer values, or in several runs");
}

}  // namespace

BenchPlan parseBenchPlan(const std::vector<std::string>& rawArgs) {
  std::vector<std::string> args;
  for (size_t i = 0; i < rawArgs.size(); ++i) {
    if (rawArgs[i] == "--sweep") {
      if (i + 1 >= rawArgs.size()) throw UsageError("--sweep needs a file");
      std::vector<std::string> file = readSweepFile(rawArgs[++i]);
      args.insert(args.end(), file.begin(), file.end());
    } else {
      args.push_back(rawArgs[i]);
    }
  }
  BenchPlan plan;
  Axes axes;
  std::vector<std::string> rest;
  std::vector<std::string> caseList{"temple@alley", "temple@hall", "temple@openings"};
  axes.bounces = takeBounceList(args);
  bool casesGiven = false;
  plan.common = parseCommonOptions(args, &rest);
  for (size_t i = 0; i < rest.size(); ++i) {
    const std::string& flag = rest[i];
    if (flag == "--no-detail") {
      plan.detailFrame = false;
      continue;
    }
    if (flag == "--no-charts") {
      plan.charts = false;
      continue;
    }
    if (i + 1 >= rest.size()) throw UsageError(flag + " needs a value");
    const std::string& v = rest[++i];
    if (flag == "--cases") caseList = splitList(v), casesGiven = true;
    else if (flag == "--scale-tris") axes.scaleTris = splitList(v);
    else if (flag == "--sizes") axes.sizes = nonEmptyList(flag, v);
    else if (flag == "--spps") axes.spps = nonEmptyList(flag, v);
    else if (flag == "--strategies") axes.strategies = splitList(v);
    else if (flag == "--sorts") axes.sorts = splitList(v);
    else if (flag == "--sort-policies") axes.policies = splitList(v);
    else if (flag == "--sort-bits-list") axes.sortBits = splitList(v);
    else if (flag == "--fusions") axes.fusions = splitList(v);
    else if (flag == "--compactions") axes.compactions = splitList(v);
    else if (flag == "--trace-shades") axes.traceShades = splitList(v);
    else if (flag == "--learn-every-list") axes.learnEvery = splitList(v);
    else if (flag == "--grids") axes.grids = splitList(v);
    else if (flag == "--clamps") axes.clamps = splitList(v);
    else if (flag == "--gauss-resets") axes.resets = splitList(v);
    else if (flag == "--fixed-factors") axes.factors = splitList(v);
    else if (flag == "--tracers") axes.tracers = splitList(v);
    else if (flag == "--bvhs") axes.bvhs = splitList(v);
    else if (flag == "--sers") axes.sers = splitList(v);
    else if (flag == "--ser-hints") axes.serHints = splitList(v);
    else if (flag == "--timed-frames") plan.timedFrames = parseUint(flag, v, 1, 10000);
    else if (flag == "--warmup") plan.warmupFrames = parseUint(flag, v, 0, 10000);
    else if (flag == "--reference-spp") plan.referenceSpp = parseUint(flag, v, 1, 1 << 16);
    else if (flag == "--out-dir") plan.outDir = v;
    else throw UsageError("unknown option '" + flag + "'");
  }
  if (!axes.scaleTris.empty() && !casesGiven) caseList = {std::string(kTempleDetailName) + "@hall"};
  std::vector<BenchCase> named;
  for (const std::string& c : caseList) {
    size_t at = c.rfind('@');
    named.push_back(at == std::string::npos ? BenchCase{c, ""} : BenchCase{c.substr(0, at), c.substr(at + 1)});
  }
  plan.cases = scaleCases(named, axes.scaleTris);
  for (const BenchCase& c : plan.cases) checkCaseScene(c.scene);
  if (axes.strategies.size() == 1 && axes.strategies[0] == "all") {
    axes.strategies.clear();
    for (KeyStrategy s : allKeyStrategies())
      if (s != KeyStrategy::None) axes.strategies.push_back(toString(s));
  }

  const Settings& base = plan.common.settings;
  if (axes.tracers.empty()) axes.tracers = {toString(base.tracer)};
  if (axes.bvhs.empty()) axes.bvhs = {toString(base.bvh)};
  if (axes.bounces.empty()) axes.bounces = {std::to_string(base.bounces)};
  // Every group has its megakernel and unsorted cells at least.
  const std::vector<Settings> pathCounts = pathCountGroups(base, axes);
  checkCellCount(plan.cases.size() * pathCounts.size() * axes.bounces.size() * axes.tracers.size() * axes.bvhs.size() * 2);
  auto addCell = [&](BenchCell cell) {
    plan.cells.push_back(std::move(cell));
    checkCellCount(plan.cells.size());
  };
  for (size_t ci = 0; ci < plan.cases.size(); ++ci) {
    // One group of cells per image size and spp, bounce count, tracer and BVH layout (in that order, so the
    // tracer reallocates its path buffers once per size; the rt tracer has one layout); the runner renders a
    // reference per size, spp and bounce count.
    std::vector<Settings> groups;
    for (const Settings& paths : pathCounts)
      for (const std::string& bounces : axes.bounces)
        for (const std::string& tracer : axes.tracers)
          for (const std::string& bvh : axes.bvhs) {
            Settings g = withFlag(withFlag(withFlag(paths, "--bounces", bounces), "--tracer", tracer), "--bvh", bvh);
            if (g.tracer == Tracer::Rt && bvh != axes.bvhs.front()) continue;
            groups.push_back(g);
          }
    for (const Settings& group : groups) {
      Settings caseBase = group;
      caseBase.scene = plan.cases[ci].scene;
      caseBase.view = plan.cases[ci].view;
      caseBase.ser = Ser::Off;
      // Labels of rt cells start with "rt ", those of the wide BVH with "wide "; the binary compute tracer's
      // keep their names.
      const std::string prefix = caseBase.tracer == Tracer::Rt ? "rt " : caseBase.bvh == BvhLayout::Wide ? "wide " : "";
      // Baselines first: the megakernel and the unsorted wavefront are in every sweep.
      Settings mega = caseBase;
      mega.kernel = Kernel::Megakernel;
      mega.strategy = KeyStrategy::None;
      addCell({ci, mega, prefix + "megakernel"});
      // SER (rt megakernel only): by hit, and by hit with the hint of each --ser-hints strategy.
      for (const std::string& ser : caseBase.tracer == Tracer::Rt ? axes.sers : std::vector<std::string>{}) {
        Settings withSer = withFlag(mega, "--ser", ser);
        if (withSer.ser == Ser::On) addCell({ci, withSer, prefix + "megakernel ser"});
        if (withSer.ser != Ser::Hint) continue;
        for (const std::string& hint : axes.serHints) {
          Settings hinted = withFlag(withSer, "--strategy", hint);
          if (hinted.strategy == KeyStrategy::None) throw UsageError("--ser-hints: a hint needs a key strategy");
          addCell({ci, hinted, prefix + "megakernel ser+hint " + hint});
        }
      }
      Settings plain = caseBase;
      plain.kernel = Kernel::Wavefront;
      plain.strategy = KeyStrategy::None;
      addCell({ci, plain, prefix + "none"});
      // The unsorted wavefront with each other value of an axis that changes it (compaction, trace and shade):
      // a baseline of its own, labelled "none <flag>=<value>".
      auto unsortedVariants = [&](const std::vector<std::string>& values, const std::string& flag, auto field) {
        for (const std::string& value : values) {
          Settings other = withFlag(plain, flag, value);
          if (other.*field != plain.*field)
            addCell({ci, other, prefix + "none " + flag.substr(2) + "=" + toString(other.*field)});
        }
      };
      unsortedVariants(axes.compactions, "--compaction", &Settings::compaction);
      unsortedVariants(axes.traceShades, "--trace-shade", &Settings::traceShade);
      for (const std::string& strategy : axes.strategies) {
        Settings st = withFlag(plain, "--strategy", strategy);
        if (st.strategy == KeyStrategy::None) continue;
        for (const std::string& sort : axes.sorts) {
          Settings so = withFlag(st, "--sort", sort);
          std::vector<Settings> variants{so};
          auto expand = [&](const std::vector<std::string>& values, const char* flag, bool gridOnly = true) {
            if (values.empty() || (gridOnly && !usesGrid(so.strategy))) return;
            checkCellCount(plan.cells.size() + variants.size() * values.size());
            std::vector<Settings> next;
            for (const Settings& v : variants)
              for (const std::string& value : values) next.push_back(withFlag(v, flag, value));
            variants = next;
          };
          expand(axes.grids, "--grid");
          expand(axes.clamps, "--clamp");
          if (strategyInfo(so.strategy).samplesGaussian) expand(axes.resets, "--gauss-reset");
          if (strategyInfo(so.strategy).readsFixedLength) expand(axes.factors, "--fixed-factor");
          expand(axes.sortBits, "--sort-bits", /*gridOnly=*/false);
          expand(axes.fusions, "--fusion", /*gridOnly=*/false);
          expand(axes.compactions, "--compaction", /*gridOnly=*/false);
          expand(axes.traceShades, "--trace-shade", /*gridOnly=*/false);
          if (usesLengthCache(so.strategy)) expand(axes.learnEvery, "--learn-every");
          checkCellCount(plan.cells.size() + variants.size() * axes.policies.size());
          std::vector<Settings> withPolicies;
          for (const Settings& v : variants)
            for (const std::string& policy : axes.policies) withPolicies.push_back(withFlag(v, "--sort-policy", policy));
          for (const Settings& v : withPolicies) {
            std::string label = prefix + strategy + "/" + sort;
            if (usesGrid(v.strategy)) {
              label += v.grid.automatic ? " grid=auto" : " grid=" + std::to_string(v.grid.cells.x) + "x" +
                                                           std::to_string(v.grid.cells.y) + "x" + std::to_string(v.grid.cells.z);
              label += v.clampToCamera ? " clamp=" + std::to_string(int(v.clampDistance)) : " clamp=off";
            }
            if (!axes.resets.empty() && strategyInfo(v.strategy).samplesGaussian) label += " reset=" + shortNumber(v.gaussReset);
            if (!axes.factors.empty() && strategyInfo(v.strategy).readsFixedLength)
              label += " factor=" + shortNumber(v.fixedFactor);
            if (v.sortPolicy != SortPolicy::Always) label += " policy=" + toString(v.sortPolicy);
            if (v.sortBits != 0) label += " bits=" + std::to_string(v.sortBits);
            if (v.fusion != Settings{}.fusion) label += " fusion=" + toString(v.fusion);
            if (v.compaction != Settings{}.compaction) label += " compaction=" + toString(v.compaction);
            if (v.traceShade != Settings{}.traceShade) label += " trace-shade=" + toString(v.traceShade);
            if (v.learnEvery != 1) label += " learn=1/" + std::to_string(v.learnEvery);
            addCell({ci, v, label});
          }
        }
      }
    }
  }
  return plan;
}

std::string benchHelp() {
  return "usage: raylab bench [render flags] [sweep flags]\n"
         "  --cases SCENE@VIEW,...    default temple@alley,temple@hall,temple@openings\n"
         "  --scale-tris 1e4,1e5,...  one case per size for every bare temple-detail case (default case\n"
         "                            temple-detail@hall): the scene-scale sweep\n"
         "  --bounces 2,4,8,16        path lengths to sweep (each case renders its reference per count)\n"
         "  --sizes 512x256,1024x512  image sizes to sweep (default: --size's); with --spps, the paths per\n"
         "                            frame (width x height x spp) as an axis; a reference per size and spp\n"
         "  --spps 1,4                samples per frame to sweep (default: --spp's)\n"
         "  --strategies all|a,b,...  key strategies besides the baselines (default all)\n"
         "  --sorts radix,bitonic     sorts to sweep (default radix)\n"
         "  --sort-policies always,auto  sort policies to sweep (default always)\n"
         "  --sort-bits-list 0,8,16   sorted key bits to sweep (0: all; see --sort-bits)\n"
         "  --fusions none,both       reorder stage fusions to sweep (see --fusion)\n"
         "  --compactions none,shade  compactions to sweep, the unsorted baseline's too (see --compaction)\n"
         "  --trace-shades split,fused  trace and shade as one dispatch or two, the baseline's too (--trace-shade)\n"
         "  --learn-every-list 1,4,16 learning strides of the length-cache strategies to sweep\n"
         "  --grids auto,32x8x32      grid settings to sweep\n"
         "  --clamps off,50           camera clamp distances to sweep\n"
         "  --gauss-resets 20,inf     Gaussian reset thresholds to sweep\n"
         "  --fixed-factors 0.5,0.25  fixed-length factors to sweep (every strategy that reads the fixed length)\n"
         "  --tracers compute,rt      tracers to sweep (default: --tracer's); rt labels start with \"rt \"\n"
         "  --bvhs binary,wide        the compute tracer's BVH layouts to sweep (default: --bvh's); wide\n"
         "                            labels start with \"wide \"\n"
         "  --sers on,hint            SER cells of the rt megakernel (by hit; by hit with a key hint)\n"
         "  --ser-hints two-point,... key strategies whose keys make the SER hint (default two-point)\n"
         "  --timed-frames N          measured frames per cell (default 8)\n"
         "  --warmup N                unmeasured frames first (default 2)\n"
         "  --reference-spp N         samples of the megakernel reference image (default 64)\n"
         "  --no-detail               skip the untimed counting frame (no SIMT/accuracy figures)\n"
         "  --no-charts               write no charts (by default the sweep ends by running\n"
         "                            python3 app/bench_charts.py DIR; RAYLAB_PYTHON picks the interpreter)\n"
         "  --out-dir DIR             results.jsonl (each cell as it ends), results.csv (at the end) and\n"
         "                            sweep.json (the sweep and the git revision) (default bench-out)\n"
         "  --resume DIR              continue a sweep that was killed: run only the cells not yet in\n"
         "                            DIR/results.jsonl; the same flags as that sweep (or none: those in\n"
         "                            DIR/sweep.json), at the same revision, else exit 2\n"
         "  --sweep FILE              the same flags as `name = value` lines\n"
         "  --shard i/K               run only the cells n (0-based, in plan order) with n mod K = i, 0 <= i < K:\n"
         "                            one of K disjoint parts of the sweep, for K GPUs or hosts\n"
         "  --merge DIR... [--out-dir OUT]  put the K shard folders of one sweep back together (CSV, JSONL,\n"
         "                            charts); refuses folders of other sweeps or revisions, or a shard missing\n"
         "The megakernel and the unsorted wavefront are always measured, per tracer. The charts (needs\n"
         "matplotlib; without python3 or matplotlib the sweep says so and keeps its CSV) can be drawn again with\n"
         "  python3 app/bench_charts.py DIR\n"
         "Exit status: 0 every cell measured and charted (or charts unavailable), 1 a cell failed, a result could\n"
         "not be written or a chart failed (results.csv and results.jsonl are kept), 2 a bad sweep (before any\n"
         "rendering), 4 validation errors.\n";
}

}  // namespace raylab
