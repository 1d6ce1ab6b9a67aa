#include "app/bench/bench_sweep.h"

#include "app/bench/case_views.h"
#include "app/setting_flags.h"
#include "renderer/reorder/key_strategies.h"
#include "renderer/settings/settings_table.h"
#include "scenes/scene_library.h"
#include "scenes/temple_detail.h"

#include <algorithm>
#include <fstream>
#include <map>
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

// The sweep's axes. The settings' own (grids, clamps, sort bits, ...) come from the settings table's rows
// (SettingAxis); the ones below make the cases, groups and baselines.
struct Axes {
  std::vector<std::string> strategies{"all"}, sorts{"radix"};
  std::vector<std::string> tracers{}, sers{}, serHints{"two-point"};
  std::vector<std::string> bvhs{};        // --bvhs: empty keeps the render flag's (binary); compute tracer only
  std::vector<std::string> bounces{};     // --bounces with a list: one group of cells per count
  std::vector<std::string> scaleTris{};   // --scale-tris: the sizes of every bare temple-detail case
  std::vector<std::string> sizes{};       // --sizes: image sizes (WxH); empty keeps --size's
  std::vector<std::string> spps{};        // --spps: samples per frame; empty keeps --spp's
  std::map<std::string, std::vector<std::string>> method;  // by setting flag; absent: the base's value

  Axes() {
    for (const SettingRow& r : settingRows())
      if (r.axis.flag && !r.axis.defaults.empty()) method[r.flag] = r.axis.defaults;
  }
  const std::vector<std::string>& of(const std::string& flag) const {
    static const std::vector<std::string> none;
    auto it = method.find(flag);
    return it == method.end() ? none : it->second;
  }
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

// Axes multiply: a sweep file of under 1 KB listing four axes 40 times each is 2.6 million cells, which
// took minutes and gigabytes to plan before anything rendered (found by tests/fuzz). Far more cells than
// any bench could render in a day is a mistake in the sweep, said before the plan grows that far.
constexpr size_t kMaxCells = 10000;
void checkCellCount(size_t cells) {
  if (cells > kMaxCells)
    throw UsageError("the sweep expands to more than " + std::to_string(kMaxCells) +
                     " cells (cases x bounces x tracers x methods); sweep fewer values, or in several runs");
}

// The order in which the settings' axes multiply (the plan's cell order) and in which their parts follow in
// a label. A row with an axis not named here comes after these, in the table's order.
const char* const kExpandOrder[] = {"grid",   "clamp",      "gauss-reset", "fixed-factor", "sort-bits",
                                    "fusion", "compaction", "trace-shade", "learn-every",  "sort-policy"};
const char* const kLabelOrder[] = {"grid",      "clamp",  "gauss-reset", "fixed-factor", "sort-policy",
                                   "sort-bits", "fusion", "compaction",  "trace-shade",  "learn-every"};

template <size_t N>
std::vector<const SettingRow*> axisRows(const char* const (&order)[N]) {
  std::vector<const SettingRow*> rows;
  for (const char* flag : order) rows.push_back(findSettingRow(flag));
  for (const SettingRow& r : settingRows())
    if (r.axis.flag && std::find(rows.begin(), rows.end(), &r) == rows.end()) rows.push_back(&r);
  return rows;
}

// `--sweep FILE` replaced by the flags of its lines.
std::vector<std::string> withSweepFiles(const std::vector<std::string>& rawArgs) {
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
  return args;
}

struct SweepFlags {
  std::vector<std::string> cases{"temple@alley", "temple@hall", "temple@openings"};
  bool casesGiven = false;
  std::vector<std::string> given;  // the sweep flags given, for the combinations a camera path refuses
};

// One sweep flag with its value; false for a flag the sweep does not know.
bool parseSweepFlag(const std::string& flag, const std::string& v, BenchPlan& plan, Axes& axes, SweepFlags& sweep) {
  sweep.given.push_back(flag);
  if (flag == "--camera-path") plan.cameraPath = v;
  else if (flag == "--cases") sweep.cases = splitList(v), sweep.casesGiven = true;
  else if (flag == "--scale-tris") axes.scaleTris = splitList(v);
  else if (flag == "--sizes") axes.sizes = nonEmptyList(flag, v);
  else if (flag == "--spps") axes.spps = nonEmptyList(flag, v);
  else if (flag == "--strategies") axes.strategies = splitList(v);
  else if (flag == "--sorts") axes.sorts = splitList(v);
  else if (flag == "--tracers") axes.tracers = splitList(v);
  else if (flag == "--bvhs") axes.bvhs = splitList(v);
  else if (flag == "--sers") axes.sers = splitList(v);
  else if (flag == "--ser-hints") axes.serHints = splitList(v);
  else if (flag == "--timed-frames") plan.timedFrames = parseUint(flag, v, 1, 10000);
  else if (flag == "--warmup") plan.warmupFrames = parseUint(flag, v, 0, 10000);
  else if (flag == "--reference-spp") plan.referenceSpp = parseUint(flag, v, 1, 1 << 16);
  else if (flag == "--rounds") plan.rounds = parseUint(flag, v, 1, kMaxRounds);
  else if (flag == "--out-dir") plan.outDir = v;
  else {
    for (const SettingRow& r : settingRows())
      if (r.axis.flag && flag == std::string("--") + r.axis.flag) return axes.method[r.flag] = splitList(v), true;
    return false;
  }
  return true;
}

void parseSweepFlags(const std::vector<std::string>& rest, BenchPlan& plan, Axes& axes, SweepFlags& sweep) {
  for (size_t i = 0; i < rest.size(); ++i) {
    const std::string& flag = rest[i];
    if (flag == "--no-detail" || flag == "--no-charts") {
      (flag == "--no-detail" ? plan.detailFrame : plan.charts) = false;
      continue;
    }
    if (i + 1 >= rest.size()) throw UsageError(flag + " needs a value");
    if (!parseSweepFlag(flag, rest[++i], plan, axes, sweep)) throw UsageError("unknown option '" + flag + "'");
  }
}

std::vector<BenchCase> planCases(const SweepFlags& sweep, const Axes& axes) {
  std::vector<std::string> caseList = sweep.cases;
  if (!axes.scaleTris.empty() && !sweep.casesGiven) caseList = {std::string(kTempleDetailName) + "@hall"};
  std::vector<BenchCase> named;
  for (const std::string& c : caseList) {
    size_t at = c.rfind('@');
    named.push_back(at == std::string::npos ? BenchCase{c, ""} : BenchCase{c.substr(0, at), c.substr(at + 1)});
  }
  std::vector<BenchCase> cases = scaleCases(named, axes.scaleTris);
  for (const BenchCase& c : cases) checkCaseScene(c.scene);
  for (const BenchCase& c : named) checkCaseView(c.scene, c.view);  // after every name: scenes load here
  return cases;
}

// The cells of one case, added in plan order (each group's baselines first); prefix: "rt ", "binary " or "".
struct CaseCells {
  BenchPlan& plan;
  const Axes& axes;
  size_t caseIndex;
  std::string prefix;

  void add(const Settings& s, const std::string& label) {
    plan.cells.push_back({caseIndex, s, prefix + label});
    checkCellCount(plan.cells.size());
  }
  void addBaselines(const Settings& caseBase, const Settings& plain);
  void addSorted(const Settings& plain);
  std::string label(const Settings& v, const std::string& strategy, const std::string& sort) const;
};

void CaseCells::addBaselines(const Settings& caseBase, const Settings& plain) {
  // The megakernel and the unsorted wavefront are in every sweep.
  Settings mega = caseBase;
  mega.kernel = Kernel::Megakernel;
  mega.strategy = KeyStrategy::None;
  add(mega, "megakernel");
  // SER (rt megakernel only): by hit, and by hit with the hint of each --ser-hints strategy.
  for (const std::string& ser : caseBase.tracer == Tracer::Rt ? axes.sers : std::vector<std::string>{}) {
    Settings withSer = withFlag(mega, "--ser", ser);
    if (withSer.ser == Ser::On) add(withSer, "megakernel ser");
    if (withSer.ser != Ser::Hint) continue;
    for (const std::string& hint : axes.serHints) {
      Settings hinted = withFlag(withSer, "--strategy", hint);
      if (hinted.strategy == KeyStrategy::None) throw UsageError("--ser-hints: a hint needs a key strategy");
      add(hinted, "megakernel ser+hint " + hint);
    }
  }
  add(plain, "none");
  // The unsorted wavefront with each other value of an axis that changes it (compaction, trace and shade):
  // a baseline of its own, labelled "none <flag>=<value>".
  for (const SettingRow& r : settingRows())
    if (r.axis.baselineToo)
      for (const std::string& value : axes.of(r.flag)) {
        Settings other = withFlag(plain, "--" + r.flag, value);
        if (!r.same(other, plain)) add(other, "none " + r.flag + "=" + r.text(other));
      }
}

std::string CaseCells::label(const Settings& v, const std::string& strategy, const std::string& sort) const {
  std::string label = strategy + "/" + sort;
  for (const SettingRow* r : axisRows(kLabelOrder))
    if (r->axis.label && (!r->axis.labelWhenSwept || !axes.of(r->flag).empty())) label += r->axis.label(v);
  return label;
}

// Every strategy and sort, times each axis of the settings that applies to the strategy.
void CaseCells::addSorted(const Settings& plain) {
  for (const std::string& strategy : axes.strategies) {
    Settings st = withFlag(plain, "--strategy", strategy);
    if (st.strategy == KeyStrategy::None) continue;
    for (const std::string& sort : axes.sorts) {
      std::vector<Settings> variants{withFlag(st, "--sort", sort)};
      for (const SettingRow* r : axisRows(kExpandOrder)) {
        const std::vector<std::string>& values = axes.of(r->flag);
        if (values.empty() || (r->axis.applies && !(strategyInfo(variants.front().strategy).*r->axis.applies))) continue;
        checkCellCount(plan.cells.size() + variants.size() * values.size());
        std::vector<Settings> next;
        for (const Settings& v : variants)
          for (const std::string& value : values) next.push_back(withFlag(v, "--" + r->flag, value));
        variants = next;
      }
      for (const Settings& v : variants) add(v, label(v, strategy, sort));
    }
  }
}

// One group of cells per image size and spp, bounce count, tracer and BVH layout (in that order, so the
// tracer reallocates its path buffers once per size; the rt tracer has one layout); the runner renders a
// reference per size, spp and bounce count.
std::vector<Settings> cellGroups(const std::vector<Settings>& pathCounts, const Axes& axes) {
  std::vector<Settings> groups;
  for (const Settings& paths : pathCounts)
    for (const std::string& bounces : axes.bounces)
      for (const std::string& tracer : axes.tracers)
        for (const std::string& bvh : axes.bvhs) {
          Settings g = withFlag(withFlag(withFlag(paths, "--bounces", bounces), "--tracer", tracer), "--bvh", bvh);
          if (g.tracer == Tracer::Rt && bvh != axes.bvhs.front()) continue;
          groups.push_back(g);
        }
  return groups;
}

void addCells(BenchPlan& plan, const Axes& axes) {
  const std::vector<Settings> pathCounts = pathCountGroups(plan.common.settings, axes);
  // Every group has its megakernel and unsorted cells at least.
  checkCellCount(plan.cases.size() * pathCounts.size() * axes.bounces.size() * axes.tracers.size() * axes.bvhs.size() * 2);
  for (size_t ci = 0; ci < plan.cases.size(); ++ci)
    for (const Settings& group : cellGroups(pathCounts, axes)) {
      Settings caseBase = group;
      caseBase.scene = plan.cases[ci].scene;
      caseBase.view = plan.cases[ci].view;
      caseBase.ser = Ser::Off;
      // Labels of rt cells start with "rt ", those of a BVH layout other than the default with its name
      // ("binary "); the default compute tracer's keep their names.
      const std::string prefix = caseBase.tracer == Tracer::Rt          ? "rt "
                                 : caseBase.bvh != Settings{}.bvh ? toString(caseBase.bvh) + " "
                                                                   : "";
      CaseCells cells{plan, axes, ci, prefix};
      Settings plain = caseBase;
      plain.kernel = Kernel::Wavefront;
      plain.strategy = KeyStrategy::None;
      cells.addBaselines(caseBase, plain);
      cells.addSorted(plain);
    }
}

}  // namespace

// A camera path sets every frame's camera and how many frames a cell renders: flags that set either, or that
// belong to still frames (a reference image, an error curve), make no sense with it.
void checkPathPlan(BenchPlan& plan, const SweepFlags& sweep, const std::vector<std::string>& args) {
  auto given = [&](const char* flag) {
    return std::find(sweep.given.begin(), sweep.given.end(), flag) != sweep.given.end() ||
           std::find(args.begin(), args.end(), flag) != args.end();
  };
  if (plan.cameraPath.empty()) return;
  if (plan.cameraPath.front() == '-') throw UsageError("--camera-path needs a file or builtin:NAME");
  for (const char* flag : {"--timed-frames", "--reference-spp"})
    if (given(flag))
      throw UsageError(std::string("--camera-path times every frame of the path, with no reference image: ") + flag +
                       " does not apply (cap the path's frames with --frames)");
  if (!sweep.casesGiven) {  // the default cases are views of the temple: with a path, the temple itself
    std::vector<BenchCase> scenes;
    for (const BenchCase& c : plan.cases)
      if (std::none_of(scenes.begin(), scenes.end(), [&](const BenchCase& s) { return s.scene == c.scene; }))
        scenes.push_back({c.scene, ""});
    plan.cases = scenes;
  }
  for (const BenchCase& c : plan.cases) {
    if (!c.view.empty())
      throw UsageError("--camera-path moves the camera every frame: give it or a view in --cases (" + c.scene + "@" +
                       c.view + "), not both");
    checkCasePath(c.scene, plan.cameraPath);
  }
  if (given("--frames")) plan.pathFramesCap = plan.common.settings.frames;
}

BenchPlan parseBenchPlan(const std::vector<std::string>& rawArgs) {
  std::vector<std::string> args = withSweepFiles(rawArgs);
  BenchPlan plan;
  Axes axes;
  SweepFlags sweep;
  std::vector<std::string> rest;
  axes.bounces = takeBounceList(args);
  plan.common = parseCommonOptions(args, &rest);
  parseSweepFlags(rest, plan, axes, sweep);
  plan.cases = planCases(sweep, axes);
  checkPathPlan(plan, sweep, args);
  if (axes.strategies.size() == 1 && axes.strategies[0] == "all") {
    axes.strategies.clear();
    for (KeyStrategy s : allKeyStrategies())
      if (s != KeyStrategy::None) axes.strategies.push_back(toString(s));
  }
  const Settings& base = plan.common.settings;
  if (axes.tracers.empty()) axes.tracers = {toString(base.tracer)};
  if (axes.bvhs.empty()) axes.bvhs = {toString(base.bvh)};
  if (axes.bounces.empty()) axes.bounces = {std::to_string(base.bounces)};
  addCells(plan, axes);
  return plan;
}

}  // namespace raylab
