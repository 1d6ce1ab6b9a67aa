#include "app/tracebench/tracebench_command.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <optional>

#include "app/scene_setup.h"
#include "app/tracebench/trace_rays.h"
#include "renderer/bvh/embree_scene.h"
#include "renderer/checked_write.h"
#include "renderer/git_revision.h"
#include "renderer/gpu_scene.h"
#include "renderer/path_tracer.h"
#include "renderer/vk/compute_pipeline.h"
#include "renderer/vk/gpu_buffer.h"
#include "renderer/vk/gpu_timer.h"
#include "renderer/vk/stage_timer.h"
#include "renderer/vk/vk_context.h"
#include "shaders/hit_query_types.h"
#include "shaders/spec_ids.h"

namespace raylab {
namespace {

const char* kTraceBenchUsage =
    "usage: raylab tracebench [options]\n"
    "  --scene NAME|FILE    scene (as render; default the built-in temple)\n"
    "  --view NAME          viewpoint (default the scene's first)\n"
    "  --size WxH|NAME      camera rays, one a pixel (default 2048x1024)\n"
    "  --bvh binary|sbvh|wide    the tree traversed (default as render)\n"
    "  --wide-collapse greedy|sah  the wide tree's collapse (as render)\n"
    "  --kinds K[,K...]     camera|bounce|shadow (default all three)\n"
    "  --repeat R           timed rounds, 1..1000 (default 10), after --warmup rounds (default 3)\n"
    "  --seed S             seed of the bounce and shadow directions (default 1)\n"
    "  --check N            rays of each kind compared with Embree, 0..1000000 (default 4096)\n"
    "  --csv FILE           also write the table as CSV\n"
    "  --device NAME|N      Vulkan device (as render)\n"
    "  --validate[=sync|gpu-av]  the Khronos validation layer (exit 1 on any error)\n";

// A kind of ray, as the table names it and the traversal it takes.
enum class RayKind { Camera, Bounce, Shadow };
struct RayKindInfo {
  RayKind kind;
  const char* name;
  uint32_t query;  // RL_HIT_QUERY_*
};
constexpr RayKindInfo kRayKinds[] = {{RayKind::Camera, "camera", RL_HIT_QUERY_CLOSEST},
                                     {RayKind::Bounce, "bounce", RL_HIT_QUERY_CLOSEST},
                                     {RayKind::Shadow, "shadow", RL_HIT_QUERY_OCCLUDED}};

struct TraceBenchOptions {
  CommonOptions common;
  std::vector<RayKind> kinds{RayKind::Camera, RayKind::Bounce, RayKind::Shadow};
  uint32_t repeat = 10, warmup = 3, seed = 1, check = 4096;
  std::string csv;
};

TraceBenchOptions parseTraceBenchOptions(std::vector<std::string> args) {
  TraceBenchOptions o;
  if (auto v = takeFlag(args, "--kinds")) {
    o.kinds.clear();
    size_t start = 0;
    while (start <= v->size()) {
      const size_t comma = std::min(v->find(',', start), v->size());
      const std::string name = v->substr(start, comma - start);
      const auto* info = std::find_if(std::begin(kRayKinds), std::end(kRayKinds),
                                      [&](const RayKindInfo& k) { return name == k.name; });
      if (info == std::end(kRayKinds)) throw UsageError("--kinds: unknown kind '" + name + "' (camera, bounce, shadow)");
      if (std::find(o.kinds.begin(), o.kinds.end(), info->kind) == o.kinds.end()) o.kinds.push_back(info->kind);
      start = comma + 1;
    }
  }
  if (auto v = takeFlag(args, "--repeat")) o.repeat = parseUint("--repeat", *v, 1, 1000);
  if (auto v = takeFlag(args, "--warmup")) o.warmup = parseUint("--warmup", *v, 0, 1000);
  if (auto v = takeFlag(args, "--seed")) o.seed = parseUint("--seed", *v, 0, 0xFFFFFFFFu);
  if (auto v = takeFlag(args, "--check")) o.check = parseUint("--check", *v, 0, 1000000);
  if (auto v = takeFlag(args, "--csv")) o.csv = *v;
  // Of the flags every mode shares, the ones that say what is traced; the others (bounces, strategies, ...)
  // describe a render and would be silently ignored here.
  const std::vector<std::string> shared = {"--scene", "--view", "--size", "--bvh", "--wide-collapse", "--device"};
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--help" || a == "-h") continue;
    if (a == "--validate" || a.rfind("--validate=", 0) == 0) continue;
    if (std::find(shared.begin(), shared.end(), a) != shared.end()) {
      ++i;  // its value
      continue;
    }
    std::vector<std::string> known = shared;
    for (const char* k : {"--kinds", "--repeat", "--warmup", "--seed", "--check", "--csv", "--validate"}) known.push_back(k);
    throw UsageError(unknownOptionMessage(a, known));
  }
  const bool sizeGiven = std::find(args.begin(), args.end(), "--size") != args.end();
  o.common = parseCommonOptions(args);
  if (!sizeGiven) o.common.settings.width = 2048, o.common.settings.height = 1024;
  return o;
}

struct KindResult {
  const RayKindInfo* info = nullptr;
  uint32_t rays = 0;
  std::vector<double> ms;  // one per timed round
  double hitFraction = 0.0;  // closest: rays that hit; shadow: rays blocked
  uint32_t checked = 0, disagreements = 0;
};

double medianMs(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : (v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]));
}

// The GPU's answers for `rays` against Embree's on an even sample of `limit` rays: the closest hit is the
// same triangle or lies at the same distance (1e-4 relative: a tie between triangles sharing the point);
// a shadow ray is blocked or not alike. Returns the disagreements.
uint32_t compareWithEmbree(const EmbreeScene& embree, const RaySet& rays, const std::vector<glm::uvec4>& gpu,
                           uint32_t query, uint32_t limit, uint32_t& checked) {
  checked = std::min(limit, rays.size());
  uint32_t bad = 0;
  for (uint32_t s = 0; s < checked; ++s) {
    const uint32_t i = static_cast<uint32_t>(uint64_t(s) * rays.size() / checked);
    const glm::vec3 o(rays.origins[i]), d(rays.directions[i]);
    const float tMax = rays.directions[i].w;
    if (query == RL_HIT_QUERY_OCCLUDED) {
      bad += embree.occluded(o, d, tMax) != (gpu[i].z != 0u);
      continue;
    }
    const EmbreeHit want = embree.intersect(o, d, tMax);
    float t;
    std::memcpy(&t, &gpu[i].x, sizeof t);
    const bool gpuHit = t > 0.0f, embreeHit = want.t >= 0.0f;
    if (gpuHit != embreeHit) {
      ++bad;
    } else if (gpuHit && gpu[i].y != want.triangle && std::abs(t - want.t) > 1e-4f * std::max(1.0f, want.t)) {
      ++bad;
    }
  }
  return bad;
}

int runTraceBench(const TraceBenchOptions& o) {
  const Settings& s = o.common.settings;
  LoadedScene loaded = loadSceneForSettings(s);
  ContextOptions co = contextOptionsFor(o.common);
  co.quiet = true;
  VulkanContext ctx(co);
  const DeviceInfo& dev = ctx.info();
  if (!deviceTimesCompute(ctx, "raylab tracebench")) return kExitFailure;
  const GpuSceneData scene(ctx, loaded.scene, s.wideCollapse);
  const gpu::GpuScene block = scene.block(s.bvh);
  GpuBuffer blockBuffer = makeBufferFrom(ctx, std::vector<gpu::GpuScene>{block});
  // The trace stage's shape: its group size, no step counting (hit_query's default counts them for tests),
  // and one traversal a pipeline.
  auto pipelineFor = [&](uint32_t queries) {
    return ComputePipeline(ctx, "hit_query", sizeof(gpu::HitQueryPush), RL_PATH_GROUP_SIZE,
                           {{RL_SPEC_COUNTS_STEPS, 0}, {RL_SPEC_HIT_QUERIES, queries}});
  };
  const ComputePipeline closest = pipelineFor(RL_HIT_QUERY_CLOSEST), occluded = pipelineFor(RL_HIT_QUERY_OCCLUDED);
  auto pipelineOf = [&](uint32_t queries) -> const ComputePipeline& {
    return queries == RL_HIT_QUERY_OCCLUDED ? occluded : closest;
  };

  // The rays: camera rays, traced once to find the surface points the other kinds start from.
  std::vector<RaySet> sets(std::size(kRayKinds));
  sets[0] = cameraRays(makeGpuCamera(loaded.view, s.width, s.height), s.width, s.height);
  auto trace = [&](const RaySet& rays) {
    GpuBuffer origins = makeBufferFrom(ctx, rays.origins), directions = makeBufferFrom(ctx, rays.directions);
    GpuBuffer results(ctx, std::max<VkDeviceSize>(16, VkDeviceSize(rays.size()) * 16));
    const gpu::HitQueryPush push{blockBuffer.address(), origins.address(), directions.address(), results.address(),
                                 rays.size(), 0};
    ctx.submitAndWait([&](VkCommandBuffer cmd) {
      closest.dispatchThreads(cmd, push, rays.size());
      computeBarrier(cmd);
    });
    return results.downloadVector<glm::uvec4>(rays.size());
  };
  {
    const std::vector<glm::uvec4> hits = trace(sets[0]);
    std::vector<float> t(hits.size());
    std::vector<uint32_t> triangle(hits.size());
    for (size_t i = 0; i < hits.size(); ++i) {
      std::memcpy(&t[i], &hits[i].x, sizeof(float));
      triangle[i] = hits[i].y;
    }
    const std::vector<SurfacePoint> points = surfacePoints(sets[0], t, triangle, loaded.scene.triangles);
    sets[1] = bounceRays(points, o.seed);
    sets[2] = shadowRays(points, loaded.scene, block.skyLightProbability, o.seed + 1);
  }

  // Every kind's buffers on the device, then all rounds in one submission: warm-up rounds, then timed ones,
  // each kind once a round in the order given (interleaved, back to back: no idle gap lets the clocks fall).
  struct Device {
    GpuBuffer origins, directions, results;
    gpu::HitQueryPush push{};
  };
  std::vector<KindResult> results;
  std::vector<Device> onDevice;
  for (RayKind kind : o.kinds) {
    const RayKindInfo& info = kRayKinds[static_cast<size_t>(kind)];
    const RaySet& rays = sets[static_cast<size_t>(kind)];
    Device d{makeBufferFrom(ctx, rays.origins.empty() ? std::vector<glm::vec4>(1) : rays.origins),
             makeBufferFrom(ctx, rays.directions.empty() ? std::vector<glm::vec4>(1) : rays.directions),
             GpuBuffer(ctx, std::max<VkDeviceSize>(16, VkDeviceSize(rays.size()) * 16))};
    d.push = {blockBuffer.address(), d.origins.address(), d.directions.address(), d.results.address(), rays.size(), 0};
    onDevice.push_back(std::move(d));
    results.push_back({&info, rays.size()});
  }
  const uint32_t rounds = o.warmup + o.repeat;
  GpuTimer timer(ctx, rounds * static_cast<uint32_t>(o.kinds.size()));
  ctx.submitAndWait([&](VkCommandBuffer cmd) {
    timer.reset(cmd);
    for (uint32_t round = 0; round < rounds; ++round)
      for (size_t k = 0; k < onDevice.size(); ++k) {
        {
          timer.setBounce(static_cast<int>(k));  // the scopes are all the trace stage; collect() keeps them in order
          ScopedStage scope(&timer, cmd, "trace");
          pipelineOf(results[k].info->query).dispatchThreads(cmd, onDevice[k].push, onDevice[k].push.count);
        }
        computeBarrier(cmd);
      }
  });
  const std::vector<StageTime> times = timer.collect();
  for (size_t i = 0; i < times.size(); ++i)
    if (i / onDevice.size() >= o.warmup) results[i % onDevice.size()].ms.push_back(times[i].ms);

  const EmbreeScene embree(loaded.scene.triangles);
  bool allAgree = true;
  std::printf("tracebench: %s, view %s, %ux%u camera rays, %s BVH; device %s (driver %s); %u rounds after %u "
              "warm-up\n",
              loaded.scene.name.c_str(), loaded.view.name.c_str(), s.width, s.height, toString(s.bvh).c_str(),
              dev.name.c_str(), dev.driver.c_str(), o.repeat, o.warmup);
  std::printf("%-7s %10s %10s %10s %10s %9s %8s %9s  %s\n", "kind", "rays", "median_ms", "min_ms", "max_ms",
              "Grays/s", "spread%", "hit_frac", "check (Embree)");
  std::string csv = "kind,rays,median_ms,min_ms,max_ms,rays_per_second,spread_percent,hit_fraction,checked,"
                    "disagreements,scene,view,width,height,bvh,repeat,warmup,seed,device,driver,revision\n";
  for (size_t k = 0; k < results.size(); ++k) {
    KindResult& r = results[k];
    const std::vector<glm::uvec4> answers = onDevice[k].results.downloadVector<glm::uvec4>(r.rays);
    uint32_t positive = 0;
    for (const glm::uvec4& a : answers) {
      float t;
      std::memcpy(&t, &a.x, sizeof t);
      positive += r.info->query == RL_HIT_QUERY_OCCLUDED ? a.z != 0u : t > 0.0f;
    }
    r.hitFraction = r.rays ? double(positive) / r.rays : 0.0;
    r.disagreements = compareWithEmbree(embree, sets[static_cast<size_t>(r.info->kind)], answers, r.info->query,
                                        o.check, r.checked);
    // Rays grazing an edge or a shared vertex may go either way in two different (correct) intersectors.
    const bool agrees = r.disagreements * 1000ull <= r.checked;
    allAgree = allAgree && agrees;
    const double med = medianMs(r.ms), lo = *std::min_element(r.ms.begin(), r.ms.end()),
                 hi = *std::max_element(r.ms.begin(), r.ms.end());
    const double raysPerSecond = med > 0.0 ? r.rays / (med * 1e-3) : 0.0;
    const double spread = med > 0.0 ? 100.0 * (hi - lo) / med : 0.0;
    char check[96];
    std::snprintf(check, sizeof check, "%s (%u of %u differ)", agrees ? "ok" : "MISMATCH", r.disagreements, r.checked);
    std::printf("%-7s %10u %10.4f %10.4f %10.4f %9.3f %8.1f %9.4f  %s\n", r.info->name, r.rays, med, lo, hi,
                raysPerSecond * 1e-9, spread, r.hitFraction, check);
    char line[512];
    std::snprintf(line, sizeof line, "%s,%u,%.6f,%.6f,%.6f,%.0f,%.2f,%.6f,%u,%u,", r.info->name, r.rays, med, lo, hi,
                  raysPerSecond, spread, r.hitFraction, r.checked, r.disagreements);
    auto quoted = [](std::string text) {
      std::replace(text.begin(), text.end(), '"', '\'');
      return "\"" + text + "\"";
    };
    csv += line + quoted(loaded.scene.name) + "," + quoted(loaded.view.name) + "," + std::to_string(s.width) + "," +
           std::to_string(s.height) + "," + toString(s.bvh) + "," + std::to_string(o.repeat) + "," +
           std::to_string(o.warmup) + "," + std::to_string(o.seed) + "," + quoted(dev.name) + "," + quoted(dev.driver) +
           "," + gitRevision() + "\n";
  }
  if (!o.csv.empty()) writeFileChecked(o.csv, csv);  // a WriteError: exit 1 (runTraceBenchCommand)
  if (co.validation != ValidationMode::Off && ctx.validationErrors() > 0) {
    std::fprintf(stderr, "raylab tracebench: the validation layer reported %u errors\n", ctx.validationErrors());
    return kExitFailure;
  }
  if (!allAgree) std::fprintf(stderr, "raylab tracebench: the GPU's answers disagree with Embree's (see check)\n");
  return allAgree ? kExitOk : kExitFailure;
}

}  // namespace

int runTraceBenchCommand(const std::vector<std::string>& args) {
  if (std::find(args.begin(), args.end(), "--help") != args.end() ||
      std::find(args.begin(), args.end(), "-h") != args.end()) {
    std::fputs(kTraceBenchUsage, stdout);
    return kExitOk;
  }
  // Device failures and an unknown --device propagate to main, which reports them (exit 1 and 2).
  return withCommandErrors([](const std::string& e) { printUsageError("raylab tracebench", e); },
                           [&] { return runTraceBench(parseTraceBenchOptions(args)); });
}

}  // namespace raylab
