// The one source of truth for what is rendered and how: the CLI parses into it, the UI edits it, the
// benchmark sweeps it and a screenshot's sidecar records it. Comparing with the previous Settings, once
// (SettingsChange::between), decides what must be reallocated, restarted or uploaded. Every member has its row
// in the settings table (renderer/settings/settings_table.h: flag, JSON, CSV, range, help, effect), which all of those
// read; tests/cpu/settings/test_settings_table.cpp fails for a member without one.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/clutter.h"

namespace raylab {

enum class KeyStrategy {
  None,             // no key, no sort: the plain wavefront
  DeadLast,         // 0 for live paths, max for finished ones
  Fixed,            // end point at a fixed fraction of the scene's largest extent
  Average,          // length cache: running average
  Ema,              // length cache: exponential moving average
  Gaussian,         // length cache: Welford mean/variance, sampled from N(mean, sigma)
  Origin,           // Meister et al.: origin cell
  Direction,        // Meister et al.: direction octahedral cell
  OriginDirection,  // Meister et al.: origin and direction interleaved
  TwoPoint,         // Meister et al.: origin and estimated end point interleaved
  Oracle,           // the true hit point, found by tracing once more (upper bound)
};

// `tile` (an experiment of issue 11: sorting within blocks that stay in shared memory instead of globally)
// sorts each tile of SORT_BITONIC_TILE consecutive slots on its own, one dispatch; the finished paths must
// have been packed behind the live ones first (Settings::compaction, every sorted bounce), so it needs
// compaction=shade on the compute tracer and no keys made in shade (settingsError says so).
// Measured on an H200 (docs/results/h200-tile): 0.04-0.14 ms a sorted bounce against 0.10-0.16 for the global
// radix sort of two-point keys, but it keeps almost none of the trace gain (hall, 4 bounces, trace of bounces
// >= 1: 2.12 ms unsorted, 1.49 radix, 1.96 tile), so every frame is slower than unsorted. Kept as a setting
// for the record; the auto policy declines it.
// `onesweep` is the radix sort with each pass in one dispatch (decoupled look-back, renderer/reorder/gpu_sort.h):
// 2 dispatches and 1 barrier a pass fewer. Its work groups wait on earlier ones, so on devices that promise no
// forward progress between work groups (CPU devices such as lavapipe) it runs one work group per dispatch:
// the same order, slowly. Issue 36 measures it against `radix`.
enum class SortAlgorithm { None, Bitonic, Radix, Tile, OneSweep };

// What the display shows instead of the render (per pixel, for one bounce).
enum class HeatmapView {
  None,            // the render itself
  SortKey,         // the path's sort key, coloured by Settings::heatmapKeyColour
  CellHit,         // estimated end-point cell equals the actual cell (green) or not (red)
  TraversalSteps,  // BVH traversal loop iterations
  WarpEfficiency,  // efficiency of the 32-wide warp this path was traced in, over its pixels
  CacheMean,       // length-cache mean at the path's (cell, octant)
  CacheVariance,   // length-cache variance there
};
// How the sort-key view colours a key: by the grid cell the key encodes (position colours: neighbouring
// cells, neighbouring colours), by its rank among the bounce's sorted keys (a ramp from first to last), or
// hashed (equal keys share a colour, nothing else reads from it).
enum class HeatmapKeyColour { Cell, Rank, Hash };
// How a scalar view's value maps onto the colour ramp between the range's ends.
enum class HeatmapScale { Linear, Log };
// The colour range of scalar views (traversal steps, warp efficiency, cache mean and variance). Unlocked it
// follows each frame's values (warp efficiency: always 0..1); locked it stays [min, max] whatever a frame
// holds, so views of different strategies compare colour for colour.
struct HeatmapRange {
  bool locked = false;
  float min = 0.0f;
  float max = 1.0f;
  bool operator==(const HeatmapRange&) const = default;
};
enum class Kernel { Wavefront, Megakernel };
// Who traverses: our BVH in compute shaders, or the driver through VK_KHR_ray_tracing_pipeline.
enum class Tracer { Compute, Rt };
// Shader Execution Reordering in the rt megakernel: off, by hit (hit object), or by hit with a coherence hint
// made of the top bits of the key of Settings::strategy.
enum class Ser { Off, On, Hint };
// Which bounces sort when a strategy is set (renderer/reorder/sort_policy.h): every one but the last, none,
// or those where earlier frames measured that sorting saves more than it costs.
enum class SortPolicy { Always, Never, Auto };

// Which reorder stages of the compute wavefront run inside a neighbouring stage instead of as passes of
// their own: `keys` computes the sort key in shade, where the next ray is born (not for the oracle, whose key
// needs that ray traced first); `gather` moves the path state through the sorted indices in the next trace,
// which reads the ray it moved instead of reading it again. Same keys, same permutation, same image; fewer
// dispatches, barriers and passes over memory. The rt tracer and the megakernels keep the setting but do
// not use it (as SER outside the rt megakernel).
// Measured on an H200 (docs/results/h200-fusion): `gather` made every sorted frame faster (0.09-0.79 ms; on
// the hall the 0.16 ms gather pass per sorted bounce became 0.03 ms more trace), so it is the default; `keys` made shade
// slower by more than the keys pass cost on the hall and Sponza (shade +0.21 ms against keys 0.13 ms, fixed,
// hall, 4 bounces) and paid only where few paths live (openings, 8 bounces: 2.39 -> 2.24 ms): opt-in.
enum class Fusion { None, Keys, Gather, Both };
// Compaction of finished paths in the compute wavefront: `shade` writes the paths it keeps alive to a packed
// prefix of the other state set (one atomic per subgroup; shaders/shade.comp) instead of in place, so later
// stages (trace, shade, and keys, sort and reorder where a sort follows) visit only live paths, in full
// warps. Every bounce but the last, sorted or not, except where shade makes the keys (Fusion::Keys). Same
// image bit for bit (a path's id, not its slot, picks its pixel and random numbers).
// Measured on an H200 (docs/results/archive/h200-compaction): the unsorted frame 0.70-0.97x (openings at 8 bounces to
// the hall at 4), more than sorting ever gained there; on lavapipe 0.62-0.90x on alley, openings and Sponza.
// So it is the default. With coarse keys (fixed, 8 sorted bits) the sorted frames lose 0.1-0.2 ms: the stable
// sort keeps equal keys in slot order, which compaction scrambles at subgroup granularity.
enum class Compaction { None, Shade };
// The compute wavefront's trace and shade of a bounce as two dispatches (`split`: the hit goes through memory
// between them) or one (`fused`: shade.comp traces the ray it loaded, timed as the stage "trace+shade"): no hit
// records written and read, one read of the path instead of two, one dispatch and barrier less. Only where
// nothing reads the hits between trace and shade (length-cache learning after a sort, detailed statistics, a
// heatmap of that bounce, keys made in shade, a trace that gathers after a sort); those bounces stay split.
// Same image bit for bit (the same traversal of the same floats).
// Measured on an H200 (docs/results/archive/h200-trace-shade): unsorted frames 0.92-0.99x, sorted ones never slower;
// with compaction the unsorted wavefront is then within 5% of the megakernel but on the hall at 4 bounces.
// The default stays split, the per-stage view the timing panel teaches; use fused for GPU measurements.
// `loop`: fused, and the bounces after the frame's last sort (every bounce when it sorts none) run as one
// dispatch, each thread tracing and shading its path to the end (shade.comp's bounce loop, timed as one
// "trace+shade" stage at its first bounce), as the megakernel does: no dispatch, barrier, indirect size or
// path-state write and read between those bounces (issue 36: the wavefront's fixed cost at small sizes). Not
// with --sort-policy auto, which times every bounce's work on its own. Same image bit for bit.
enum class TraceShade { Split, Fused, Loop };

// Which BVH the compute tracer walks (GpuScene::bvhLayout): the binary tree or the compressed 8-wide one
// collapsed from it (renderer/bvh/bvh_wide.h). Both index the same BVH-order triangles; the wide traversal may pick
// another of two triangles hit at the same t, so switching restarts the image (and the invariant holds within
// one layout). The rt tracer ignores it. A traversal step counts a node of the chosen layout (docs).
// sbvh: the binary tree built again with spatial splits (renderer/bvh/bvh.h, BvhSplits::Spatial) over the same
// BVH order, walked by the binary traversal: the default, the fastest frame of every cell measured on an H200
// (docs/results/h200-sbvh: Sponza, the hall and the clutter room at 1e6 triangles, 1920x1080 and 4096x2048,
// 4 bounces, unsorted, two-point and the megakernel; frames 1.09-1.42x faster than binary, 1.05-1.56x than wide).
// Binary and wide win no cell there; they stay for comparison (wide: the BVH order comes from its collapse).
enum class BvhLayout { Binary, Sbvh, Wide };
// How the wide BVH is collapsed from the binary one (renderer/bvh/bvh_wide_slots.h): greedy (open the largest-area
// subtree until 8) or SAH-optimal (Ylitie et al.'s dynamic program). The collapse moves the triangles into its
// leaf order, which both layouts and the emitter table read: another collapse is another scene (built again,
// the image restarts). On an H200 (docs/results/h200-wide-bvh/sah-collapse: 5 cases, 2048x1024 and 4096x2048,
// 4 and 8 bounces, wide BVH) sah's frames are a median 2% faster than greedy's (the temple's views 2-6%,
// Sponza sorted 2%), slower only on the cluttered room (2-6%); the binary BVH's frames do not move with the
// order (within 0.3%). Sah is the default; greedy stays for the room and for comparison.
enum class WideCollapse { Greedy, Sah };

const std::vector<KeyStrategy>& allKeyStrategies();
std::string toString(KeyStrategy s);
std::string toString(SortAlgorithm s);
std::string toString(Kernel k);
// Parsers return nothing for unknown names; the CLI lists the accepted ones.
std::optional<KeyStrategy> parseKeyStrategy(const std::string& name);
std::optional<SortAlgorithm> parseSortAlgorithm(const std::string& name);
std::optional<Kernel> parseKernel(const std::string& name);
std::string toString(Tracer t);
std::string toString(Ser s);
std::optional<Tracer> parseTracer(const std::string& name);
std::optional<Ser> parseSer(const std::string& name);
std::string toString(SortPolicy p);
std::optional<SortPolicy> parseSortPolicy(const std::string& name);
std::string toString(Fusion f);
std::optional<Fusion> parseFusion(const std::string& name);
std::string toString(Compaction c);
std::optional<Compaction> parseCompaction(const std::string& name);
std::string toString(TraceShade t);
std::optional<TraceShade> parseTraceShade(const std::string& name);
std::string toString(BvhLayout b);
std::optional<BvhLayout> parseBvhLayout(const std::string& name);
std::string toString(WideCollapse c);
std::string keyStrategyNames();  // "none|dead-last|fixed|..."
std::string toString(HeatmapView v);
std::string toString(HeatmapKeyColour c);
std::string toString(HeatmapScale s);
std::optional<HeatmapKeyColour> parseHeatmapKeyColour(const std::string& name);
std::optional<HeatmapScale> parseHeatmapScale(const std::string& name);
std::optional<HeatmapView> parseHeatmapView(const std::string& name);
const std::vector<HeatmapView>& allHeatmapViews();
// Every value of a settings enum, in the order the help and the window list them (KeyStrategy, SortAlgorithm,
// HeatmapView, HeatmapKeyColour, HeatmapScale, Kernel, Tracer, Ser, SortPolicy, Fusion, Compaction,
// TraceShade, BvhLayout, WideCollapse).
template <class E>
const std::vector<E>& allValues();

// Grid resolution: automatic (near-cubic cells from the extents) or explicit cells per axis.
struct GridSetting {
  bool automatic = true;
  uint32_t autoCells = 64;      // cells along the largest axis when automatic
  glm::uvec3 cells{64, 64, 64};  // explicit cells per axis
  bool operator==(const GridSetting&) const = default;
};

// Limits where the methods are defined: the settings table's rows (renderer/settings/settings_table.cpp) take their
// ranges from here; validation rejects values outside (whichever way they came in), the UI sliders clamp to
// them.
struct SettingLimits {
  static constexpr uint32_t kMaxSize = 8192;
  static constexpr uint32_t kMaxBounces = 32;
  static constexpr uint32_t kMaxSpp = 64;
  // Any count a uint32 holds: a window left accumulating on a GPU passes a million frames within the hour,
  // and its screenshot's sidecar (frames = those accumulated) must still re-render.
  static constexpr uint32_t kMaxFrames = 4294967295u;
  static constexpr uint64_t kMaxPathsPerFrame = 1ull << 26;  // 8192x8192 at 1 spp
  static constexpr float kMaxExposure = 1e6f;
  static constexpr uint32_t kMaxGridCellsPerAxis = 1024;  // 10 bits per axis: 30-bit Morton keys
  static constexpr uint32_t kMaxBvhReinsertPasses = 64;
  static constexpr float kMaxBvhPresplit = 1.0f;  // a cut for every triangle at most
  static constexpr float kMaxClampDistance = 1e6f;
  static constexpr float kMinFixedFactor = 0.0f;
  static constexpr float kMaxFixedFactor = 4.0f;
  static constexpr float kMinEmaAlpha = 0.001f;
  static constexpr float kMaxEmaAlpha = 1.0f;
  static constexpr float kMaxGaussOutlier = 100.0f;
  static constexpr float kMaxHeatmapValue = 1e30f;  // a locked heatmap range's ends
};

struct Settings {
  // Scene and camera
  std::string scene = "temple";  // built-in name or a .gltf/.glb path
  std::string view;              // viewpoint name; empty: the scene's first
  uint32_t clutterSeed = kClutterDefaultSeed;  // the cluttered room's layout; other scenes ignore it
  uint32_t width = 512;
  uint32_t height = 256;
  uint32_t bounces = 4;
  uint32_t sppPerFrame = 1;
  uint32_t frames = 1;
  uint32_t seed = 1;
  float exposure = 1.0f;
  Kernel kernel = Kernel::Wavefront;
  Tracer tracer = Tracer::Compute;
  BvhLayout bvh = BvhLayout::Sbvh;  // compute tracer only (docs/results/h200-sbvh)
  WideCollapse wideCollapse = WideCollapse::Sah;  // the scene's wide BVH (both tracers see its triangle order)
  // Passes of insertion-based optimization over the spatial-split tree (renderer/bvh/bvh_reinsert.h), each of the
  // worst 1% of its interior nodes; 0: Embree's tree as built. Another tree is another scene (built again).
  // An option: on the H200 5 passes make Sponza's frame trace 4-7% faster, temple-detail's 3-4% slower and the
  // clutter room's megakernel 4% longer (docs/results/h200-tree-variants; steps: lavapipe-tree-steps).
  uint32_t bvhReinsert = 0;
  // Cuts before the spatial-split tree's build (renderer/bvh/bvh_presplit.h), a fraction of the triangle count;
  // 0: none. Another tree is another scene. The default since the rule that never cuts an axis-aligned
  // triangle (the hall's ground, whose cuts had made it 4-8% slower: docs/results/h200-tree-variants): on an H100
  // 0.001 made Sponza's frame trace 11-17% faster on camera rays and 13% on bounce rays, the study's other scenes
  // within 1%, the Cornell box's bounce rays 1.8% slower (docs/results/h100-presplit-warp-orders).
  float bvhPresplit = 0.001f;
  Ser ser = Ser::Off;  // rt tracer's megakernel only

  // Reordering
  KeyStrategy strategy = KeyStrategy::None;
  SortAlgorithm sort = SortAlgorithm::Radix;
  SortPolicy sortPolicy = SortPolicy::Always;
  // The sort orders only the top `sortBits` bits of the key (0: all of them): each 8 bits fewer is one radix
  // pass less. Coarser order, same image (the invariant); whether the trace still profits is the bench's call.
  uint32_t sortBits = 0;
  Fusion fusion = Fusion::Gather;
  Compaction compaction = Compaction::Shade;
  TraceShade traceShade = TraceShade::Split;
  GridSetting grid;
  bool clampToCamera = false;
  float clampDistance = 50.0f;
  float fixedFactor = 0.5f;   // the study's; Meister et al. use 0.25
  float emaAlpha = 0.2f;
  float gaussOutlier = 3.0f;  // sigmas beyond which a sample is an outlier
  float gaussReset = 20.0f;   // variance above which a cell restarts (the study's tuned value)
  // Length-cache learning reads every learnEvery-th slot of the sorted rays (1: all of them): a stratified
  // sample of the key order, so each cell still learns; cheaper learning, a noisier mean. 1..64.
  uint32_t learnEvery = 1;

  // Measurement and display
  bool countSimt = false;  // subgroup-ballot counting in the traversal loop (not for timed runs)
  HeatmapView heatmap = HeatmapView::None;
  uint32_t heatmapBounce = 1;  // which bounce the heatmap shows (0 = camera rays)
  HeatmapKeyColour heatmapKeyColour = HeatmapKeyColour::Cell;
  HeatmapScale heatmapScale = HeatmapScale::Linear;
  HeatmapRange heatmapRange;

  // Settings::fusion as this tracer applies it: only the compute wavefront's stages fuse.
  bool fusesKeys() const { return sorts() && tracer == Tracer::Compute && strategy != KeyStrategy::Oracle &&
                                  (fusion == Fusion::Keys || fusion == Fusion::Both); }
  bool fusesGather() const { return sorts() && tracer == Tracer::Compute && (fusion == Fusion::Gather || fusion == Fusion::Both); }
  // Settings::traceShade as this tracer applies it: only the compute wavefront, and not while counting SIMT
  // lanes (the counting trace variant).
  bool fusesTraceShade() const { return traceShade != TraceShade::Split && kernel == Kernel::Wavefront && tracer == Tracer::Compute && !countSimt; }
  // TraceShade::Loop as this tracer applies it (where it fuses trace and shade).
  bool loopsBounces() const { return traceShade == TraceShade::Loop && fusesTraceShade(); }
  // Settings::compaction as this tracer applies it: only the compute wavefront compacts.
  bool compacts() const { return compaction == Compaction::Shade && kernel == Kernel::Wavefront && tracer == Tracer::Compute; }
  bool sorts() const { return kernel == Kernel::Wavefront && strategy != KeyStrategy::None && sort != SortAlgorithm::None; }
  // SER runs only in the rt megakernel; elsewhere the setting is kept but does nothing.
  bool reordersInHardware() const { return tracer == Tracer::Rt && kernel == Kernel::Megakernel && ser != Ser::Off; }
  // True when the image of `previous` cannot be accumulated into: anything that changes what a pixel converges to.
  bool requiresAccumulationReset(const Settings& previous) const;
  // True when length caches learned under `previous` no longer apply.
  bool requiresCacheReset(const Settings& previous) const;
  bool operator==(const Settings&) const = default;
};

// What going from one Settings to the next requires of the renderer. PathTracer computes it once per
// change and passes it down. KeyStage keeps the settings it was last given, for the one caller without a
// change to pass (its configure(), which the GPU tests of keys call).
struct SettingsChange {
  bool reallocate = false;         // the path count changed (size, samples per frame): new path buffers
  bool resetAccumulation = false;  // Settings::requiresAccumulationReset: the image starts again
  bool resetCache = false;         // Settings::requiresCacheReset: what the length caches learned is void
  bool keyParameters = false;      // the key grid, cache thresholds or path bound changed: rebuild, upload
  bool resetSortCosts = false;     // what the auto sort policy measured no longer holds (another view,
                                   // image, key, sort, policy or kernel): measure again

  static SettingsChange between(const Settings& previous, const Settings& next);
  // What the renderer must do for a change with these effects (the table's kEffect* bits, or-ed over the
  // settings that differ), with what they imply: new caches or path buffers mean new key parameters, and
  // any change at all voids the sort policy's measured costs.
  static SettingsChange fromEffects(unsigned effects);
  // A camera move: the image starts again; the key grid moves only when it is clamped to the camera.
  static SettingsChange cameraMove(const Settings& settings);
  bool operator==(const SettingsChange&) const = default;
};

}  // namespace raylab
