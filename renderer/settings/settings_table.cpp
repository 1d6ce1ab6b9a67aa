// The settings table's rows, in the order of the command line's help (renderer/settings/settings_table.h says what
// reads them). Ranges are SettingLimits'; defaults are Settings'.
#include "renderer/settings/settings_table.h"

#include <stdexcept>

#include "renderer/reorder/key_strategies.h"
#include "renderer/settings/settings_rows.h"

namespace raylab {
namespace {

using namespace setting_rows;
using L = SettingLimits;
constexpr unsigned kAccumulation = kEffectAccumulation, kCache = kEffectCache, kSortCosts = kEffectSortCosts;

std::string shortNumber(float v) {
  char text[32];
  std::snprintf(text, sizeof(text), "%g", v);
  return text;
}
// A label part " NAME=VALUE" where the value is not the default.
template <class T>
std::string unlessDefault(const char* name, T Settings::*m, const Settings& s) {
  return s.*m == Settings{}.*m ? std::string() : std::string(" ") + name + "=" + Codec<T>::text(s.*m);
}

std::vector<SettingRow> sceneAndImageRows() {
  return {
      RAYLAB_FIELD(scene, "scene").json("scene").csv("scene", /*quoted=*/true)
          .effects(kEffectScene | kAccumulation | kCache)
          .help("temple|cornell|furnace|temple-detail:N|clutter:N|FILE.gltf|FILE.glb", " scene (default {default};\n"
                "temple-detail:N is the temple with N triangles, 1e4 to 3e7; clutter:N a storeroom\n"
                "of small objects with about N triangles, 5e4 to 3e6)").sample("cornell"),
      // The CSV's view column is the viewpoint the bench resolved (bench_results.cpp): empty is the first.
      RAYLAB_FIELD(view, "view").json("view").effects(kAccumulation)
          .help("NAME", "viewpoint (default: the scene's first)").sample("front"),
      RAYLAB_FIELD(clutterSeed, "clutter-seed").range(0, 4294967295.0).json("clutter_seed", keepDefault)
          .csv("clutter_seed").effects(kEffectScene | kAccumulation | kCache)
          .help("N", "layout of the cluttered room (scene clutter:N): where its objects lie\n"
                "(default {default}; other scenes ignore it)").sample("7"),
      setting_rows::sizeRow(),
      // No reallocation: path state does not depend on the bounce count (the counters have room for the most).
      RAYLAB_FIELD(bounces, "bounces").range(1, L::kMaxBounces).json("bounces").csv("bounces").effects(kAccumulation)
          .help("N", "path length in bounces, {range} (default {default})").sample("7"),
      RAYLAB_FIELD(sppPerFrame, "spp").range(1, L::kMaxSpp).json("spp_per_frame").csv("spp_per_frame")
          .effects(kEffectReallocate | kAccumulation).help("N", "samples per pixel per frame, {range} (default {default})")
          .sample("3"),
      RAYLAB_FIELD(frames, "frames").range(1, L::kMaxFrames).json("frames")
          .help("N", "frames to accumulate (default {default})").sample("9"),
      RAYLAB_FIELD(seed, "seed").range(0, 4294967295.0).json("seed").effects(kAccumulation)
          .help("N", "random seed (default {default})").sample("42"),
  };
}

std::vector<SettingRow> tracerRows() {
  return {
      RAYLAB_FIELD(kernel, "kernel").json("kernel").jsonError("unknown kernel, strategy or sort").csv("kernel")
          .effects(kSortCosts).help("wavefront|megakernel", "").sample("megakernel"),
      RAYLAB_FIELD(tracer, "tracer").jsonAbsent("tracer", "compute").jsonError("unknown tracer").csv("tracer")
          .effects(kSortCosts).help("compute|rt", "our BVH in compute shaders (default), or VK_KHR_ray_tracing_pipeline")
          .sample("rt"),
      // Another layout may break ties between equally near triangles otherwise: a new image.
      RAYLAB_FIELD(bvh, "bvh").jsonAbsent("bvh", "binary").csv("bvh").effects(kAccumulation)
          .help("binary|sbvh|wide", "compute tracer: the binary BVH, the binary BVH with spatial splits\n"
                "(SBVH; the default), or the compressed 8-wide one collapsed from the first (quantized\n"
                "child boxes, as CWBVH)").sample("binary"),
      RAYLAB_FIELD(wideCollapse, "wide-collapse").jsonAbsent("wide_collapse", "greedy").csv("wide_collapse")
          .effects(kEffectScene | kAccumulation | kCache)
          .help("greedy|sah", "how the wide BVH is collapsed from the binary one: open the largest subtree\n"
                "first, or SAH-optimal (Ylitie et al.) (default {default}); the scene is built again")
          .sample("greedy"),
      RAYLAB_FIELD(bvhReinsert, "bvh-reinsert").range(0, SettingLimits::kMaxBvhReinsertPasses)
          .json("bvh_reinsert", keepDefault).csv("bvh_reinsert").effects(kEffectScene | kAccumulation | kCache)
          .help("N", "passes of insertion-based optimization of the sbvh tree, each of its worst 1%\n"
                "of interior nodes, {range} (default {default}: Embree's tree); the scene is built again")
          .sample("5"),
      RAYLAB_FIELD(bvhPresplit, "bvh-presplit").range(0, SettingLimits::kMaxBvhPresplit)
          .json("bvh_presplit", keepDefault).csv("bvh_presplit").effects(kEffectScene | kAccumulation | kCache)
          .help("F", "cuts of the triangle boxes with the most empty space (never an axis-aligned triangle's)\n"
                "before the sbvh tree's build, as a fraction of the triangle count, {range} (default {default};\n"
                "0: none); the scene is built again")
          .sample("0"),
      RAYLAB_FIELD(ser, "ser").jsonAbsent("ser", "off").jsonError("unknown ser").csv("ser").effects(kSortCosts)
          .help("off|on|hint", "rt megakernel: Shader Execution Reordering by hit, or by hit with the\n"
                "top bits of --strategy's key as coherence hint (needs a strategy)").sample("hint"),
  };
}

std::vector<SettingRow> sortRows() {
  return {
      RAYLAB_FIELD(strategy, "strategy").json("strategy").jsonError("unknown kernel, strategy or sort").csv("strategy")
          .effects(kCache).help(keyStrategyNames().c_str(), "").sample("ema"),
      RAYLAB_FIELD(sort, "sort").json("sort").jsonError("unknown kernel, strategy or sort").csv("sort").effects(kSortCosts)
          .help("none|bitonic|radix|tile|onesweep", "sort used when a strategy is set (default {default});\n"
                "tile sorts each 2048 paths alone (needs --compaction shade); onesweep:\n"
                "radix with a dispatch a pass (on CPU devices one work group at a time)").sample("bitonic"),
      RAYLAB_FIELD(sortPolicy, "sort-policy").jsonAbsent("sort_policy", "always").jsonError("unknown sort policy")
          .csv("sort_policy").effects(kSortCosts)
          .help("always|never|auto", "which bounces sort: all, none, or where earlier frames measured\n"
                "a saving (default {default})").sample("auto")
          .axis({"sort-policies", "always,auto  sort policies to sweep (default always)", nullptr,
                 [](const Settings& s) { return unlessDefault("policy", &Settings::sortPolicy, s); }, {"always"}}),
      RAYLAB_FIELD(sortBits, "sort-bits").range(0, 32).json("sort_bits", keepDefault).csv("sort_bits").effects(kSortCosts)
          .help("N", "order only the key's top N bits, {range} (default {default}: all); 8 bits\n"
                "fewer is one radix pass less").sample("8")
          .axis({"sort-bits-list", "0,8,16   sorted key bits to sweep (0: all; see --sort-bits)", nullptr,
                 [](const Settings& s) { return unlessDefault("bits", &Settings::sortBits, s); }}),
      // Older sidecars lack these; the value is what those versions did: every reorder stage a pass of its own,
      // finished paths in their slots, trace and shade two dispatches.
      RAYLAB_FIELD(fusion, "fusion").jsonAbsent("fusion", "none").csv("fusion").effects(kSortCosts)
          .help("none|keys|gather|both", "compute wavefront: keys made in shade, the reorder done by the\n"
                "next trace (same image; default {default})").sample("both")
          .axis({"fusions", "none,both       reorder stage fusions to sweep (see --fusion)", nullptr,
                 [](const Settings& s) { return unlessDefault("fusion", &Settings::fusion, s); }}),
      RAYLAB_FIELD(compaction, "compaction").jsonAbsent("compaction", "none").csv("compaction").effects(kSortCosts)
          .help("none|shade", "compute wavefront: shade packs the live paths at the front of the\n"
                "other state set, so later stages visit only live paths (same\nimage; default {default})")
          .sample("none")
          .axis({"compactions", "none,shade  compactions to sweep, the unsorted baseline's too (see --compaction)",
                 nullptr, [](const Settings& s) { return unlessDefault("compaction", &Settings::compaction, s); }, {}, false,
                 /*baselineToo=*/true}),
      RAYLAB_FIELD(traceShade, "trace-shade").jsonAbsent("trace_shade", "split").csv("trace_shade").effects(kSortCosts)
          .help("split|fused|loop", "compute wavefront: trace and shade of a bounce as two dispatches\n"
                "(default) or one where nothing reads the hit between them; loop: fused,\n"
                "and the bounces after the last sort in one dispatch (same image)").sample("fused")
          .axis({"trace-shades", "split,fused,loop  trace and shade as one dispatch or two, the baseline's too (--trace-shade)",
                 nullptr, [](const Settings& s) { return unlessDefault("trace-shade", &Settings::traceShade, s); }, {}, false,
                 /*baselineToo=*/true}),
  };
}

std::vector<SettingRow> keyRows() {
  return {
      setting_rows::gridRow(),
      setting_rows::clampRow(),
      RAYLAB_FIELD(fixedFactor, "fixed-factor").range(L::kMinFixedFactor, L::kMaxFixedFactor).json("fixed_factor")
          .effects(kCache).help("F", "fixed length = F * largest extent (default {default}; Meister et al. 0.25)")
          .sample("0.25")
          .axis({"fixed-factors", "0.5,0.25  fixed-length factors to sweep (every strategy that reads the fixed length)",
                 &KeyStrategyInfo::readsFixedLength,
                 [](const Settings& s) { return strategyInfo(s.strategy).readsFixedLength ? " factor=" + shortNumber(s.fixedFactor) : ""; },
                 {}, /*labelWhenSwept=*/true}),
      // Thresholds: new parameters on the GPU, but what the cache learned stays.
      RAYLAB_FIELD(emaAlpha, "ema-alpha").range(L::kMinEmaAlpha, L::kMaxEmaAlpha).json("ema_alpha")
          .effects(kEffectKeyParameters).help("A", "EMA weight of a new length (default {default})").sample("0.5"),
      RAYLAB_FIELD(gaussOutlier, "gauss-outlier").range(0, L::kMaxGaussOutlier).json("gauss_outlier")
          .effects(kEffectKeyParameters).help("S", "reject lengths beyond S sigmas (default {default})").sample("2"),
      RAYLAB_FIELD(gaussReset, "gauss-reset").range(0, 3.0e38).infinity().json("gauss_reset")
          .effects(kEffectKeyParameters)
          .help("V", "reset a cell when its variance exceeds V (default {default}, 'inf' never)").sample("inf")
          .axis({"gauss-resets", "20,inf     Gaussian reset thresholds to sweep", &KeyStrategyInfo::samplesGaussian,
                 [](const Settings& s) { return strategyInfo(s.strategy).samplesGaussian ? " reset=" + shortNumber(s.gaussReset) : ""; }, {},
                 /*labelWhenSwept=*/true}),
      RAYLAB_FIELD(learnEvery, "learn-every").range(1, 64).json("learn_every", keepDefault).csv("learn_every")
          .effects(kSortCosts).help("N", "length caches learn from every N-th sorted ray, {range} (default {default})")
          .sample("4")
          .axis({"learn-every-list", "1,4,16 learning strides of the length-cache strategies to sweep", &KeyStrategyInfo::learnsLengths,
                 [](const Settings& s) {
                   return s.learnEvery == 1 ? std::string() : " learn=1/" + std::to_string(s.learnEvery);
                 }}),
  };
}

std::vector<SettingRow> displayRows() {
  return {
      RAYLAB_FIELD(exposure, "exposure").range(0, L::kMaxExposure).json("exposure")
          .help("E", "display exposure (default {default})").sample("2"),
      // Older sidecars have no heatmap fields: they showed the render, hashed keys on a linear, per-frame range.
      RAYLAB_FIELD(heatmap, "heatmap").json("heatmap", keepDefault).jsonError("unknown heatmap view")
          .help("VIEW", "show sort-key|cell-hit|traversal-steps|warp-efficiency|cache-mean|\n"
                "cache-variance per pixel instead of the render").sample("traversal-steps"),
      RAYLAB_FIELD(heatmapBounce, "heatmap-bounce").range(0, L::kMaxBounces - 1).json("heatmap_bounce", keepDefault)
          .help("N", "bounce the heatmap shows (default {default}; 0 = camera rays)").sample("2"),
      RAYLAB_FIELD(heatmapKeyColour, "heatmap-key-colour").json("heatmap_key_colour", keepDefault)
          .whenAbsent([](const nlohmann::json& j, Settings& s) {
            if (j.contains("heatmap")) s.heatmapKeyColour = HeatmapKeyColour::Hash;
          })
          .jsonError("unknown heatmap_key_colour (cell|rank|hash)")
          .help("cell|rank|hash", "sort-key colours: the key's grid cell as a position colour\n"
                "(default), its rank among the sorted keys, or a hash (equal keys alike)").sample("rank"),
      RAYLAB_FIELD(heatmapScale, "heatmap-scale").json("heatmap_scale", keepDefault)
          .jsonError("unknown heatmap_scale (linear|log)")
          .help("linear|log", "value to colour mapping of scalar heatmaps (default {default})").sample("log"),
      setting_rows::heatmapRangeRow(),
      RAYLAB_FIELD(countSimt, "count-simt").json("count_simt")
          .help("", "count active subgroup lanes in traversal (slower; not for timing)").sample("on"),
  };
}

std::string filledHelp(const SettingRow& r) {
  std::string text = r.help;
  auto fill = [&](const std::string& key, const std::string& value) {
    for (size_t at; (at = text.find(key)) != std::string::npos;) text.replace(at, key.size(), value);
  };
  fill("{range}", formatNumber(r.lo) + ".." + formatNumber(r.hi));
  fill("{hi}", formatNumber(r.hi));
  fill("{default}", r.text(Settings{}));
  return text;
}

std::vector<SettingRow> allRows() {
  std::vector<SettingRow> rows;
  for (auto part : {sceneAndImageRows, tracerRows, sortRows, keyRows, displayRows})
    for (SettingRow& r : part()) rows.push_back(std::move(r));
  for (SettingRow& r : rows) r.help = filledHelp(r);
  return rows;
}

}  // namespace

const std::vector<SettingRow>& settingRows() {
  static const std::vector<SettingRow> rows = allRows();
  return rows;
}

const SettingRow* findSettingRow(const std::string& flag) {
  for (const SettingRow& r : settingRows())
    if (r.flag == flag) return &r;
  return nullptr;
}

NumberRange settingRange(const std::string& flag) {
  const SettingRow* r = findSettingRow(flag);
  if (!r || r->lo > r->hi) throw std::logic_error("no setting with a range named " + flag);
  return r->range();
}

std::string settingsHelp() {
  std::string help;
  for (const SettingRow& r : settingRows()) {
    std::string line = "  " + r.dashed + (r.hint.empty() ? "" : " " + r.hint);
    if (!r.help.empty()) {
      line += line.size() <= 23 ? std::string(25 - line.size(), ' ') : std::string(2, ' ');
      for (char c : r.help) line += c == '\n' ? "\n" + std::string(25, ' ') : std::string(1, c);
    }
    help += line + "\n";
  }
  return help;
}

std::map<std::string, std::string> settingsCsvColumns(const Settings& s) {
  std::map<std::string, std::string> columns;
  for (const SettingRow& r : settingRows()) r.csv(s, columns);
  return columns;
}

}  // namespace raylab
