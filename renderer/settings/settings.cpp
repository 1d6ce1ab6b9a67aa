#include "renderer/settings/settings.h"

#include <utility>

#include "renderer/reorder/key_strategies.h"
#include "renderer/settings/settings_table.h"

namespace raylab {
namespace {

const std::pair<SortAlgorithm, const char*> kSortNames[] = {
    {SortAlgorithm::None, "none"}, {SortAlgorithm::Bitonic, "bitonic"}, {SortAlgorithm::Radix, "radix"},
    {SortAlgorithm::Tile, "tile"}, {SortAlgorithm::OneSweep, "onesweep"}};
const std::pair<HeatmapView, const char*> kHeatmapNames[] = {
    {HeatmapView::None, "none"},          {HeatmapView::SortKey, "sort-key"},
    {HeatmapView::CellHit, "cell-hit"},   {HeatmapView::TraversalSteps, "traversal-steps"},
    {HeatmapView::WarpEfficiency, "warp-efficiency"}, {HeatmapView::CacheMean, "cache-mean"},
    {HeatmapView::CacheVariance, "cache-variance"}};
const std::pair<HeatmapKeyColour, const char*> kKeyColourNames[] = {
    {HeatmapKeyColour::Cell, "cell"}, {HeatmapKeyColour::Rank, "rank"}, {HeatmapKeyColour::Hash, "hash"}};
const std::pair<HeatmapScale, const char*> kScaleNames[] = {{HeatmapScale::Linear, "linear"}, {HeatmapScale::Log, "log"}};
const std::pair<Fusion, const char*> kFusionNames[] = {
    {Fusion::None, "none"}, {Fusion::Keys, "keys"}, {Fusion::Gather, "gather"}, {Fusion::Both, "both"}};
const std::pair<Compaction, const char*> kCompactionNames[] = {{Compaction::None, "none"}, {Compaction::Shade, "shade"}};
const std::pair<TraceShade, const char*> kTraceShadeNames[] = {{TraceShade::Split, "split"}, {TraceShade::Fused, "fused"}, {TraceShade::Loop, "loop"}};
const std::pair<SortPolicy, const char*> kPolicyNames[] = {
    {SortPolicy::Always, "always"}, {SortPolicy::Never, "never"}, {SortPolicy::Auto, "auto"}};
const std::pair<Kernel, const char*> kKernelNames[] = {{Kernel::Wavefront, "wavefront"},
                                                       {Kernel::Megakernel, "megakernel"}};
const std::pair<BvhLayout, const char*> kBvhLayoutNames[] = {{BvhLayout::Binary, "binary"}, {BvhLayout::Sbvh, "sbvh"}, {BvhLayout::Wide, "wide"}};
const std::pair<WideCollapse, const char*> kWideCollapseNames[] = {{WideCollapse::Greedy, "greedy"},
                                                                   {WideCollapse::Sah, "sah"}};
const std::pair<Tracer, const char*> kTracerNames[] = {{Tracer::Compute, "compute"}, {Tracer::Rt, "rt"}};
const std::pair<Ser, const char*> kSerNames[] = {{Ser::Off, "off"}, {Ser::On, "on"}, {Ser::Hint, "hint"}};

template <class E, size_t N>
std::string nameOf(const std::pair<E, const char*> (&table)[N], E value) {
  for (const auto& [v, n] : table)
    if (v == value) return n;
  return "?";
}

template <class E, size_t N>
std::optional<E> parse(const std::pair<E, const char*> (&table)[N], const std::string& name) {
  for (const auto& [v, n] : table)
    if (name == n) return v;
  return std::nullopt;
}

template <class E, size_t N>
std::vector<E> valuesOf(const std::pair<E, const char*> (&table)[N]) {
  std::vector<E> v;
  for (const auto& [e, n] : table) v.push_back(e);
  return v;
}

}  // namespace

#define RAYLAB_ALL_VALUES(E, table)                 \
  template <>                                       \
  const std::vector<E>& allValues<E>() {            \
    static const std::vector<E> all = valuesOf(table); \
    return all;                                     \
  }
RAYLAB_ALL_VALUES(SortAlgorithm, kSortNames)
RAYLAB_ALL_VALUES(HeatmapView, kHeatmapNames)
RAYLAB_ALL_VALUES(HeatmapKeyColour, kKeyColourNames)
RAYLAB_ALL_VALUES(HeatmapScale, kScaleNames)
RAYLAB_ALL_VALUES(Fusion, kFusionNames)
RAYLAB_ALL_VALUES(Compaction, kCompactionNames)
RAYLAB_ALL_VALUES(TraceShade, kTraceShadeNames)
RAYLAB_ALL_VALUES(SortPolicy, kPolicyNames)
RAYLAB_ALL_VALUES(Kernel, kKernelNames)
RAYLAB_ALL_VALUES(BvhLayout, kBvhLayoutNames)
RAYLAB_ALL_VALUES(WideCollapse, kWideCollapseNames)
RAYLAB_ALL_VALUES(Tracer, kTracerNames)
RAYLAB_ALL_VALUES(Ser, kSerNames)
#undef RAYLAB_ALL_VALUES
template <>
const std::vector<KeyStrategy>& allValues<KeyStrategy>() {
  return allKeyStrategies();
}

const std::vector<KeyStrategy>& allKeyStrategies() {
  static const std::vector<KeyStrategy> all = [] {
    std::vector<KeyStrategy> v;
    for (const KeyStrategyInfo& k : kKeyStrategies) v.push_back(k.strategy);
    return v;
  }();
  return all;
}

std::string toString(KeyStrategy s) { return strategyInfo(s).name; }
std::string toString(HeatmapView v) { return nameOf(kHeatmapNames, v); }
std::optional<HeatmapView> parseHeatmapView(const std::string& n) { return parse(kHeatmapNames, n); }
const std::vector<HeatmapView>& allHeatmapViews() { return allValues<HeatmapView>(); }
std::string toString(HeatmapKeyColour c) { return nameOf(kKeyColourNames, c); }
std::string toString(HeatmapScale s) { return nameOf(kScaleNames, s); }
std::optional<HeatmapKeyColour> parseHeatmapKeyColour(const std::string& n) { return parse(kKeyColourNames, n); }
std::optional<HeatmapScale> parseHeatmapScale(const std::string& n) { return parse(kScaleNames, n); }
std::string toString(SortAlgorithm s) { return nameOf(kSortNames, s); }
std::string toString(Kernel k) { return nameOf(kKernelNames, k); }
std::optional<KeyStrategy> parseKeyStrategy(const std::string& n) {
  for (const KeyStrategyInfo& k : kKeyStrategies)
    if (n == k.name) return k.strategy;
  return std::nullopt;
}
std::optional<SortAlgorithm> parseSortAlgorithm(const std::string& n) { return parse(kSortNames, n); }
std::optional<Kernel> parseKernel(const std::string& n) { return parse(kKernelNames, n); }
std::string toString(Tracer t) { return nameOf(kTracerNames, t); }
std::string toString(Ser s) { return nameOf(kSerNames, s); }
std::optional<Tracer> parseTracer(const std::string& n) { return parse(kTracerNames, n); }
std::optional<Ser> parseSer(const std::string& n) { return parse(kSerNames, n); }
std::string toString(SortPolicy p) { return nameOf(kPolicyNames, p); }
std::optional<SortPolicy> parseSortPolicy(const std::string& n) { return parse(kPolicyNames, n); }
std::string toString(Fusion f) { return nameOf(kFusionNames, f); }
std::optional<Fusion> parseFusion(const std::string& n) { return parse(kFusionNames, n); }
std::string toString(Compaction c) { return nameOf(kCompactionNames, c); }
std::optional<Compaction> parseCompaction(const std::string& n) { return parse(kCompactionNames, n); }
std::string toString(TraceShade t) { return nameOf(kTraceShadeNames, t); }
std::optional<TraceShade> parseTraceShade(const std::string& n) { return parse(kTraceShadeNames, n); }
std::string toString(BvhLayout b) { return nameOf(kBvhLayoutNames, b); }
std::optional<BvhLayout> parseBvhLayout(const std::string& n) { return parse(kBvhLayoutNames, n); }
std::string toString(WideCollapse c) { return nameOf(kWideCollapseNames, c); }

std::string keyStrategyNames() {
  std::string s;
  for (const KeyStrategyInfo& k : kKeyStrategies) {  // (GCC 12 -O3 warns, wrongly, of an overlap in "a" + b here)
    if (!s.empty()) s += '|';
    s += k.name;
  }
  return s;
}

namespace {

// The effects (settings_table.h) of every row in which `a` and `b` differ.
unsigned changedEffects(const Settings& a, const Settings& b) {
  unsigned effects = kEffectNone;
  for (const SettingRow& row : settingRows())
    if (!row.same(a, b)) effects |= row.effects;
  return effects;
}

}  // namespace

// Key strategy, sort and grid parameters never change the image (the central invariant), so they keep the
// accumulation; everything that changes a sample does not (the table's rows of kEffectAccumulation).
bool Settings::requiresAccumulationReset(const Settings& p) const {
  return changedEffects(*this, p) & kEffectAccumulation;
}

bool Settings::requiresCacheReset(const Settings& p) const { return changedEffects(*this, p) & kEffectCache; }

SettingsChange SettingsChange::between(const Settings& p, const Settings& n) { return fromEffects(changedEffects(p, n)); }

SettingsChange SettingsChange::fromEffects(unsigned effects) {
  // The key parameters hold the grid and thresholds, and the length unit, which follows the path count.
  if (effects & (kEffectCache | kEffectReallocate)) effects |= kEffectKeyParameters;
  // What the auto sort policy measured holds for one view, image, key, sort, policy, kernel and tracer.
  if (effects != kEffectNone) effects |= kEffectSortCosts;
  SettingsChange c;
  c.reallocate = effects & kEffectReallocate;
  c.resetAccumulation = effects & kEffectAccumulation;
  c.resetCache = effects & kEffectCache;
  c.keyParameters = effects & kEffectKeyParameters;
  c.resetSortCosts = effects & kEffectSortCosts;
  return c;
}

SettingsChange SettingsChange::cameraMove(const Settings& s) {
  SettingsChange c;
  c.resetAccumulation = true;
  c.keyParameters = s.clampToCamera;
  return c;
}

}  // namespace raylab
