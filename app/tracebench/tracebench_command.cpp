#include "app/tracebench/tracebench_command.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <optional>

#include "app/bench/bench_spread.h"
#include "app/scene_setup.h"
#include "app/tracebench/tracebench_options.h"
#include "app/tracebench/warp_fetches.h"
#include "renderer/bvh/embree_scene.h"
#include "renderer/checked_write.h"
#include "renderer/detail_sums.h"
#include "renderer/git_revision.h"
#include "renderer/gpu_scene.h"
#include "renderer/path_tracer.h"
#include "renderer/reorder/key_functions.h"
#include "renderer/reorder/key_grid.h"
#include "renderer/reorder/key_stage.h"
#include "renderer/vk/compute_pipeline.h"
#include "renderer/vk/gpu_buffer.h"
#include "renderer/vk/gpu_timer.h"
#include "renderer/vk/stage_timer.h"
#include "renderer/vk/vk_context.h"
#include "shaders/spec_ids.h"

namespace raylab {
namespace {

// hit_query.comp as the trace stage runs: its group size and one traversal a pipeline; timed without step
// counting (as the trace stage's frames without detailed figures), and once more counting them.
struct QueryPipelines {
  explicit QueryPipelines(const VulkanContext& ctx)
      : closest(make(ctx, RL_HIT_QUERY_CLOSEST, false)),
        occluded(make(ctx, RL_HIT_QUERY_OCCLUDED, false)),
        closestCounting(make(ctx, RL_HIT_QUERY_CLOSEST, true)),
        occludedCounting(make(ctx, RL_HIT_QUERY_OCCLUDED, true)) {}
  const ComputePipeline& of(uint32_t query, bool countsSteps = false) const {
    if (query == RL_HIT_QUERY_OCCLUDED) return countsSteps ? occludedCounting : occluded;
    return countsSteps ? closestCounting : closest;
  }
  static ComputePipeline make(const VulkanContext& ctx, uint32_t query, bool countsSteps) {
    return ComputePipeline(ctx, "hit_query", sizeof(gpu::HitQueryPush), RL_PATH_GROUP_SIZE,
                           {{RL_SPEC_COUNTS_STEPS, countsSteps ? 1u : 0u}, {RL_SPEC_HIT_QUERIES, query}});
  }
  ComputePipeline closest, occluded, closestCounting, occludedCounting;
};

// Rays on the device (one copy a kind, traced through every tree).
struct DeviceRays {
  DeviceRays(const VulkanContext& ctx, const RaySet& rays)
      : origins(makeBufferFrom(ctx, rays.origins.empty() ? std::vector<glm::vec4>(1) : rays.origins)),
        directions(makeBufferFrom(ctx, rays.directions.empty() ? std::vector<glm::vec4>(1) : rays.directions)),
        count(rays.size()) {}
  GpuBuffer origins, directions;
  uint32_t count;
};

// Room for one answer a ray (hit_query's uvec4) and the push that traces `rays` through `scene`'s tree.
struct DeviceAnswers {
  DeviceAnswers(const VulkanContext& ctx, const DeviceRays& rays, VkDeviceAddress scene)
      : results(ctx, std::max<VkDeviceSize>(16, VkDeviceSize(rays.count) * 16)),
        push{scene, rays.origins.address(), rays.directions.address(), results.address(), rays.count, 0} {}
  std::vector<glm::uvec4> download() const { return results.downloadVector<glm::uvec4>(push.count); }
  GpuBuffer results;
  gpu::HitQueryPush push;
};

float tOf(const glm::uvec4& answer) {
  float t;
  std::memcpy(&t, &answer.x, sizeof t);
  return t;
}

// The closest hits of `rays` through `scene`'s tree, traced once: hit distances (negative: a miss) and
// scene triangle indices.
void traceOnce(const VulkanContext& ctx, const QueryPipelines& pipelines, VkDeviceAddress scene, const RaySet& rays,
               std::vector<float>& t, std::vector<uint32_t>& triangle) {
  const DeviceRays onDevice(ctx, rays);
  const DeviceAnswers traced(ctx, onDevice, scene);
  ctx.submitAndWait([&](VkCommandBuffer cmd) {
    pipelines.closest.dispatchThreads(cmd, traced.push, rays.size());
    computeBarrier(cmd);
  });
  t.clear();
  triangle.clear();
  for (const glm::uvec4& a : traced.download()) {
    t.push_back(tOf(a));
    triangle.push_back(a.y);
  }
}

using RaySets = std::array<RaySet, std::size(kRayKinds)>;

// The ray sets: camera rays, traced once (with `scene`'s tree) to find the points the bounce and shadow rays
// start from; with --sort-rays, the bounce rays in its key's order (the oracle's key reads their true hits).
// With --sort-earlier each earlier bounce is traced in that key's order, so the bounce rays come in the order the
// last sort left (as a frame's that sorted the bounces before and not this one).
RaySets makeRaySets(const VulkanContext& ctx, const QueryPipelines& pipelines, VkDeviceAddress scene,
                    const LoadedScene& loaded, const TraceBenchOptions& o, float skyProbability) {
  const Settings& s = o.common.settings;
  RaySets sets;
  RaySet& camera = sets[size_t(RayKind::Camera)];
  camera = cameraRays(makeGpuCamera(loaded.view, s.width, s.height), s.width, s.height, o.order);
  std::vector<float> t;
  std::vector<uint32_t> triangle;
  traceOnce(ctx, pipelines, scene, camera, t, triangle);
  std::vector<SurfacePoint> points = surfacePoints(camera, t, triangle, loaded.scene.triangles);
  KeyGrid grid = makeKeyGrid(loaded.scene.bounds(), loaded.view.position, s);
  if (o.sortRays) grid.gpu.spatialBits = spatialKeyBits(*o.sortRays, grid.gpu);
  const gpu::GpuKeyParams keyParams = baseKeyParams(grid, s);
  const uint32_t ignoredBits = ignoredKeyBits(grid.gpu.spatialBits, s.sortBits);
  // --bounce-depth D: the bounce and shadow rays leave the hits of D - 1 earlier bounces, each traced here.
  for (uint32_t depth = 1; depth < o.bounceDepth; ++depth) {
    RaySet earlier = bounceRays(points, o.seed + 1000u * depth);
    if (o.sortEarlier) earlier = sortedByKey(earlier, *o.sortRays, keyParams, {}, ignoredBits);
    traceOnce(ctx, pipelines, scene, earlier, t, triangle);
    points = surfacePoints(earlier, t, triangle, loaded.scene.triangles);
  }
  const RaySet& bounce = sets[size_t(RayKind::Bounce)] = bounceRays(points, o.seed);
  sets[size_t(RayKind::Shadow)] = shadowRays(points, loaded.scene, skyProbability, o.seed + 1);
  if (o.sortRays) {
    std::vector<float> hitT;
    if (*o.sortRays == KeyStrategy::Oracle) traceOnce(ctx, pipelines, scene, bounce, hitT, triangle);
    sets[size_t(RayKind::BounceSorted)] = sortedByKey(bounce, *o.sortRays, keyParams, hitT, ignoredBits);
  }
  return sets;
}

// One row of the table: a kind of ray through one tree, its rays on the device and what was measured.
struct Cell {
  BvhLayout bvh;
  const RayKindInfo* kind;
  const RaySet* rays;
  DeviceAnswers onDevice;
  std::vector<double> ms;  // one per timed round
  double hitFraction = 0.0;  // closest hits: rays that hit; shadow rays: rays blocked
  uint32_t checked = 0, disagreements = 0;
  // The divergence the lab studies: traversal steps a ray, and the virtual warp efficiency of 32 consecutive
  // rays (their steps over 32 times the most steps among them), as the frames' detailed figures count them.
  double meanSteps = 0.0, warpEfficiency = 0.0;
  std::optional<FetchCounts> fetches;  // --fetches
};

// Every round in one submission, each cell once a round in the table's order: warm-up rounds, then timed ones,
// back to back (no idle gap in which the GPU lowers its clocks), interleaved (drift hits every cell alike).
void timeCells(const VulkanContext& ctx, const QueryPipelines& pipelines, std::vector<Cell>& cells,
               uint32_t warmup, uint32_t repeat) {
  const uint32_t rounds = warmup + repeat;
  GpuTimer timer(ctx, rounds * static_cast<uint32_t>(cells.size()));
  ctx.submitAndWait([&](VkCommandBuffer cmd) {
    timer.reset(cmd);
    for (uint32_t round = 0; round < rounds; ++round)
      for (const Cell& c : cells) {
        {
          ScopedStage scope(&timer, cmd, "trace");  // collect() returns the scopes in this order
          pipelines.of(c.kind->query).dispatchThreads(cmd, c.onDevice.push, c.onDevice.push.count);
        }
        computeBarrier(cmd);
      }
  });
  const std::vector<StageTime> times = timer.collect();
  for (size_t i = warmup * cells.size(); i < times.size(); ++i) cells[i % cells.size()].ms.push_back(times[i].ms);
  // Once more counting steps, untimed: the answers checkCell reads.
  ctx.submitAndWait([&](VkCommandBuffer cmd) {
    for (const Cell& c : cells) pipelines.of(c.kind->query, true).dispatchThreads(cmd, c.onDevice.push, c.onDevice.push.count);
    computeBarrier(cmd);
  });
}

// The GPU's answers against Embree's on an even sample of `limit` rays: the closest hit is the same triangle
// or lies at the same distance (1e-4 relative: a tie between triangles sharing the point); a shadow ray is
// blocked or not alike. Also the fraction of rays that hit (or are blocked).
void checkCell(Cell& c, const EmbreeScene& embree, uint32_t limit) {
  const std::vector<glm::uvec4> gpu = c.onDevice.download();
  const RaySet& rays = *c.rays;
  const bool shadow = c.kind->query == RL_HIT_QUERY_OCCLUDED;
  uint32_t positive = 0;
  std::vector<uint32_t> steps;
  steps.reserve(gpu.size());
  for (const glm::uvec4& a : gpu) {
    positive += shadow ? a.z != 0u : tOf(a) > 0.0f;
    steps.push_back(a.w);
  }
  c.hitFraction = rays.size() ? double(positive) / rays.size() : 0.0;
  gpu::GpuDetailSums sums{};
  addWarpSums(sums, steps);
  const double work = double(uint64_t(sums.warpWorkHi) << 32 | sums.warpWorkLo);
  const double slots = double(uint64_t(sums.warpSlotsHi) << 32 | sums.warpSlotsLo);
  c.meanSteps = rays.size() ? work / rays.size() : 0.0;
  c.warpEfficiency = slots > 0.0 ? work / slots : 0.0;
  c.checked = std::min(limit, rays.size());
  for (uint32_t s = 0; s < c.checked; ++s) {
    const uint32_t i = static_cast<uint32_t>(uint64_t(s) * rays.size() / c.checked);
    const glm::vec3 o(rays.origins[i]), d(rays.directions[i]);
    const float tMax = rays.directions[i].w;
    if (shadow) {
      c.disagreements += embree.occluded(o, d, tMax) != (gpu[i].z != 0u);
      continue;
    }
    const EmbreeHit want = embree.intersect(o, d, tMax);
    const float t = tOf(gpu[i]);
    if ((t > 0.0f) != (want.t >= 0.0f))
      ++c.disagreements;
    else if (t > 0.0f && gpu[i].y != want.triangle && std::abs(t - want.t) > 1e-4f * std::max(1.0f, want.t))
      ++c.disagreements;
  }
}

// Rays grazing an edge or a shared vertex may go either way in two different (correct) intersectors.
bool agrees(const Cell& c) { return uint64_t(c.disagreements) * 1000 <= c.checked; }

struct Figures : Spread {
  double raysPerSecond = 0, spreadPercent = 0;
};
Figures figuresOf(const Cell& c) {
  Figures f{spreadOf(c.ms)};
  f.raysPerSecond = f.median > 0.0 ? c.rays->size() / (f.median * 1e-3) : 0.0;
  f.spreadPercent = f.median > 0.0 ? 100.0 * (f.max - f.min) / f.median : 0.0;
  return f;
}

// --fetches' columns of a row: the CPU twin's counts (warp_fetches.h), -1 each where not counted.
std::string fetchColumns(const std::optional<FetchCounts>& f) {
  const FetchCounts none{-1, -1, -1, -1, -1, -1, -1, -1};
  const FetchCounts& c = f ? *f : none;
  char text[256];
  std::snprintf(text, sizeof text, ",%.4f,%.4f,%.4f,%.4f,%.4f,%.3f,%.4f,%.4f", c.meanSteps, c.nodesPerRay,
                c.warpNodesPerRay, c.entriesPerRay, c.warpEntriesPerRay, c.windowMegabytes, c.requestNodesPerRay,
                c.requestEntriesPerRay);
  return text;
}

// --fetches' table: what each cell's traversal reads, lane by lane and warp by warp, and what the rays an H200
// holds at once touch.
void reportFetches(const std::vector<Cell>& cells) {
  std::printf("reads (CPU twin of the traversal), a ray: each lane's; warp: the distinct reads of 32 consecutive "
              "rays; req: the distinct reads of each lockstep iteration (loads); node_share: lanes a distinct node "
              "read; window: distinct MB of %u rays\n", kH200ResidentThreads);
  std::printf("%-7s %-13s %7s %9s %10s %9s %9s %10s %9s %10s %10s\n", "bvh", "kind", "steps", "nodes", "warp_nodes",
              "req_nodes", "entries", "warp_entr", "req_entr", "node_share", "window_MB");
  for (const Cell& c : cells) {
    const FetchCounts& f = *c.fetches;
    std::printf("%-7s %-13s %7.2f %9.2f %10.2f %9.2f %9.2f %10.2f %9.2f %10.2f %10.2f\n", toString(c.bvh).c_str(),
                c.kind->name, f.meanSteps, f.nodesPerRay, f.warpNodesPerRay, f.requestNodesPerRay, f.entriesPerRay,
                f.warpEntriesPerRay, f.requestEntriesPerRay,
                f.warpNodesPerRay > 0 ? f.nodesPerRay / f.warpNodesPerRay : 0.0, f.windowMegabytes);
  }
}

// The table on stdout and, with --csv, the same rows with what produced them.
void report(const std::vector<Cell>& cells, const TraceBenchOptions& o, const LoadedScene& loaded,
            const DeviceInfo& dev) {
  const Settings& s = o.common.settings;
  std::printf("tracebench: %s, view %s, %ux%u camera rays (%s order)%s%s; device %s (driver %s); %u rounds after %u "
              "warm-up\n",
              loaded.scene.name.c_str(), loaded.view.name.c_str(), s.width, s.height,
              o.order == CameraRayOrder::Tiles ? "tiles" : "scanline", o.sortRays ? ", bounce-sorted by " : "",
              o.sortRays ? toString(*o.sortRays).c_str() : "", dev.name.c_str(), dev.driver.c_str(), o.repeat, o.warmup);
  std::printf("%-7s %-13s %10s %10s %10s %10s %9s %8s %9s %7s %6s  %s\n", "bvh", "kind", "rays", "median_ms",
              "min_ms", "max_ms", "Mrays/s", "spread%", "hit_frac", "steps", "warp", "check (Embree)");
  std::string csv = "bvh,kind,rays,median_ms,min_ms,max_ms,rays_per_second,spread_percent,hit_fraction,"
                    "mean_steps,warp_efficiency,checked,disagreements,scene,view,width,height,order,sort_rays,sort_bits,"
                    "bounce_depth,sort_earlier,repeat,warmup,seed,device,driver,revision,cpu_mean_steps,nodes_per_ray,"
                    "warp_nodes_per_ray,entries_per_ray,warp_entries_per_ray,window_megabytes,node_requests_per_ray,"
                    "entry_requests_per_ray\n";
  const std::string context = csvText(loaded.scene.name) + "," + csvText(loaded.view.name) + "," +
                              std::to_string(s.width) + "," + std::to_string(s.height) + "," +
                              (o.order == CameraRayOrder::Tiles ? "tiles" : "scanline") + "," +
                              (o.sortRays ? toString(*o.sortRays) : std::string("-")) + "," + std::to_string(s.sortBits) + "," +
                              std::to_string(o.bounceDepth) + "," + (o.sortEarlier ? "1" : "0") + "," +
                              std::to_string(o.repeat) + "," + std::to_string(o.warmup) + "," +
                              std::to_string(o.seed) + "," + csvText(dev.name) + "," + csvText(dev.driver) + "," +
                              gitRevision();
  for (const Cell& c : cells) {
    const Figures f = figuresOf(c);
    std::printf("%-7s %-13s %10u %10.4f %10.4f %10.4f %9.1f %8.1f %9.4f %7.2f %6.3f  %s (%u of %u differ)\n",
                toString(c.bvh).c_str(), c.kind->name, c.rays->size(), f.median, f.min, f.max, f.raysPerSecond * 1e-6,
                f.spreadPercent, c.hitFraction, c.meanSteps, c.warpEfficiency, agrees(c) ? "ok" : "MISMATCH",
                c.disagreements, c.checked);
    char line[512];
    std::snprintf(line, sizeof line, "%s,%s,%u,%.6f,%.6f,%.6f,%.0f,%.2f,%.6f,%.4f,%.6f,%u,%u,", toString(c.bvh).c_str(),
                  c.kind->name, c.rays->size(), f.median, f.min, f.max, f.raysPerSecond, f.spreadPercent,
                  c.hitFraction, c.meanSteps, c.warpEfficiency, c.checked, c.disagreements);
    csv += line + context + fetchColumns(c.fetches) + "\n";
  }
  if (o.fetches) reportFetches(cells);
  if (!o.csv.empty()) writeFileChecked(o.csv, csv);  // a WriteError reaches main: exit 1, naming the file
}

// --export: each kind's rays and the triangles, for another tracer. A folder that cannot be made is a
// WriteError too (main: exit 1, naming it).
void exportRays(const TraceBenchOptions& o, const RaySets& sets, const Scene& scene) {
  std::error_code error;
  std::filesystem::create_directories(o.exportDir, error);
  if (error) throw WriteError("cannot write " + o.exportDir + ": " + error.message());
  const std::string dir = o.exportDir + "/";
  writeFileChecked(dir + "triangles.bin", triangleBytes(scene.triangles));
  for (RayKind kind : o.kinds)
    writeFileChecked(dir + "rays-" + rayKindInfo(kind).name + ".bin", raySetBytes(sets[size_t(kind)]));
  std::printf("tracebench: wrote %zu triangles and the rays of %zu kinds to %s\n", scene.triangles.size(),
              o.kinds.size(), o.exportDir.c_str());
}

int runTraceBench(const TraceBenchOptions& o) {
  const LoadedScene loaded = loadSceneForSettings(o.common.settings);
  ContextOptions co = contextOptionsFor(o.common);
  co.quiet = true;
  VulkanContext ctx(co);
  if (!deviceTimesCompute(ctx, "raylab tracebench")) return kExitFailure;
  const GpuSceneData scene(ctx, loaded.scene, o.common.settings.wideCollapse, o.common.settings.bvhReinsert,
                           o.common.settings.bvhPresplit, o.fetches);
  std::vector<GpuBuffer> blocks;  // each tree's scene block (GpuSceneData::block)
  for (BvhLayout bvh : o.bvhs) blocks.push_back(makeBufferFrom(ctx, std::vector<gpu::GpuScene>{scene.block(bvh)}));
  const QueryPipelines pipelines(ctx);
  const RaySets sets =
      makeRaySets(ctx, pipelines, blocks.front().address(), loaded, o, scene.block(o.bvhs.front()).skyLightProbability);
  if (!o.exportDir.empty()) exportRays(o, sets, loaded.scene);
  std::vector<DeviceRays> rays;  // one copy of each kind's rays; each cell its own answers
  for (RayKind kind : o.kinds) rays.emplace_back(ctx, sets[size_t(kind)]);
  std::vector<Cell> cells;
  cells.reserve(o.bvhs.size() * o.kinds.size());
  for (size_t b = 0; b < o.bvhs.size(); ++b)
    for (size_t k = 0; k < o.kinds.size(); ++k)
      cells.push_back({o.bvhs[b], &rayKindInfo(o.kinds[k]), &sets[size_t(o.kinds[k])],
                       DeviceAnswers(ctx, rays[k], blocks[b].address())});
  timeCells(ctx, pipelines, cells, o.warmup, o.repeat);
  const EmbreeScene embree(loaded.scene.triangles);
  for (Cell& c : cells) checkCell(c, embree, o.check);
  if (o.fetches)
    for (Cell& c : cells)
      c.fetches = countFetches(scene.hostTree(c.bvh), *c.rays, c.kind->query == RL_HIT_QUERY_OCCLUDED);
  report(cells, o, loaded, ctx.info());
  if (co.validation != ValidationMode::Off && ctx.validationErrors() > 0) {
    std::fprintf(stderr, "raylab tracebench: the validation layer reported %u errors\n", ctx.validationErrors());
    return kExitFailure;
  }
  if (!std::all_of(cells.begin(), cells.end(), agrees)) {
    std::fprintf(stderr, "raylab tracebench: the GPU's answers disagree with Embree's (see check)\n");
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace

int runTraceBenchCommand(const std::vector<std::string>& args) {
  if (std::find(args.begin(), args.end(), "--help") != args.end() ||
      std::find(args.begin(), args.end(), "-h") != args.end()) {
    std::fputs(traceBenchUsage(), stdout);
    return kExitOk;
  }
  // Device failures and an unknown --device propagate to main, which reports them (exit 1 and 2).
  return withCommandErrors([](const std::string& e) { printUsageError("raylab tracebench", e); },
                           [&] { return runTraceBench(parseTraceBenchOptions(args)); });
}

}  // namespace raylab
