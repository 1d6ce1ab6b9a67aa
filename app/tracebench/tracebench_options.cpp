#include "app/tracebench/tracebench_options.h"

#include <algorithm>

#include "app/bench/bench_sweep.h"
#include "renderer/reorder/key_strategies.h"

namespace raylab {

const char* traceBenchUsage() {
  return "usage: raylab tracebench [options]\n"
         "  --scene NAME|FILE    scene (as render; default the built-in temple)\n"
         "  --view NAME          viewpoint (default the scene's first)\n"
         "  --size WxH|NAME      camera rays, one a pixel (default 2048x1024)\n"
         "  --bvhs L[,L...]      trees traversed, each in the same rounds: binary|sbvh|wide (default: --bvh's,\n"
         "                       as render)\n"
         "  --wide-collapse greedy|sah  the wide tree's collapse (as render)\n"
         "  --bvh-reinsert N     passes of optimization of the sbvh tree (as render)\n"
         "  --bvh-presplit F     cuts before the sbvh tree's build, a fraction of the triangles (as render)\n"
         "  --kinds K[,K...]     camera|bounce|shadow|bounce-sorted (default all; bounce and shadow rays start\n"
         "                       at the camera rays' hits, or --bounce-depth's)\n"
         "  --sort-rays S        also trace the bounce rays sorted by strategy S's key (bounce-sorted): a strategy\n"
         "                       that learns nothing (fixed, origin, direction, origin-direction, two-point,\n"
         "                       oracle); --grid, --clamp, --fixed-factor and --sort-bits as render\n"
         "  --bounce-depth D     bounce and shadow rays leave the hits of bounce D - 1 (1: the camera rays' hits,\n"
         "                       the default; 2: the first bounce's; up to 8), each earlier bounce traced here\n"
         "  --sort-earlier       trace the earlier bounces in --sort-rays' order (not the oracle's), so that the\n"
         "                       bounce rays come in the order the last sort left them (needs --bounce-depth 2+)\n"
         "  --fetches            also count what each ray's traversal reads, walking the same rays with its CPU\n"
         "                       twin: pair nodes and leaf entries a ray, the distinct ones of each warp of 32\n"
         "                       rays and of each of its lockstep iterations (its loads), a ray, and the distinct\n"
         "                       megabytes of each 270,336 rays (the H200's resident threads); binary and sbvh\n"
         "                       trees only\n"
         "  --order tiles|scanline  the camera rays' order: the generate stage's 8x4-pixel tiles (default) or rows\n"
         "  --repeat R           timed rounds, 1..1000 (default 10), after --warmup rounds, 0..1000 (default 3)\n"
         "  --seed S             seed of the bounce and shadow directions (default 1)\n"
         "  --check N            rays of each kind compared with Embree, 0..1000000 (default 4096)\n"
         "  --csv FILE           also write the table as CSV\n"
         "  --export DIR         also write the rays of each kind traced (DIR/rays-KIND.bin) and the scene's\n"
         "                       triangles (DIR/triangles.bin) as raw little-endian floats, for another tracer:\n"
         "                       a ray is origin xyz 0 and direction xyz tMax, a triangle three vertices xyz 0\n"
         "  --device NAME|N      Vulkan device (as render)\n"
         "  --validate[=sync|gpu-av]  the Khronos validation layer (exit 1 on any error)\n";
}

namespace {

// The flags of every mode that say what is traced; the others (bounces, strategies, ...) describe a render
// and would be ignored here without a word, so they are refused.
const std::vector<std::string> kSharedFlags = {"--scene", "--view",  "--size",  "--bvh",         "--wide-collapse",
                                               "--device", "--grid", "--clamp", "--fixed-factor", "--sort-bits",
                                               "--bvh-reinsert", "--bvh-presplit"};
const std::vector<std::string> kOwnFlags = {"--bvhs", "--kinds", "--sort-rays", "--order", "--repeat", "--warmup",
                                            "--seed", "--check", "--csv",       "--export", "--validate",
                                            "--bounce-depth", "--sort-earlier", "--fetches"};

std::vector<RayKind> parseKinds(const std::string& text) {
  std::vector<RayKind> kinds;
  for (const std::string& name : splitList(text)) {
    const auto* info = std::find_if(std::begin(kRayKinds), std::end(kRayKinds),
                                    [&](const RayKindInfo& k) { return name == k.name; });
    if (info == std::end(kRayKinds))
      throw UsageError("--kinds: unknown kind '" + name + "' (camera, bounce, shadow, bounce-sorted)");
    if (std::find(kinds.begin(), kinds.end(), info->kind) == kinds.end()) kinds.push_back(info->kind);
  }
  if (kinds.empty()) throw UsageError("--kinds needs at least one of camera, bounce, shadow, bounce-sorted");
  return kinds;
}

std::vector<BvhLayout> parseBvhs(const std::string& text) {
  std::vector<BvhLayout> bvhs;
  for (const std::string& name : splitList(text)) {
    const std::optional<BvhLayout> b = parseBvhLayout(name);
    if (!b) throw UsageError("--bvhs: unknown BVH '" + name + "' (binary, sbvh, wide)");
    if (std::find(bvhs.begin(), bvhs.end(), *b) == bvhs.end()) bvhs.push_back(*b);
  }
  if (bvhs.empty()) throw UsageError("--bvhs needs at least one of binary, sbvh, wide");
  return bvhs;
}

}  // namespace

TraceBenchOptions parseTraceBenchOptions(std::vector<std::string> args) {
  TraceBenchOptions o;
  if (auto v = takeFlag(args, "--kinds")) o.kinds = parseKinds(*v);
  if (auto v = takeFlag(args, "--bvhs")) o.bvhs = parseBvhs(*v);
  if (auto v = takeFlag(args, "--sort-rays")) {
    const std::optional<KeyStrategy> s = parseKeyStrategy(*v);
    if (!s) throw UsageError("--sort-rays: unknown strategy '" + *v + "' (" + keyStrategyNames() + ")");
    if (strategyInfo(*s).learnsLengths || *s == KeyStrategy::None || *s == KeyStrategy::DeadLast)
      throw UsageError("--sort-rays " + *v + ": " +
                       (strategyInfo(*s).learnsLengths ? "it learns lengths over frames, and a batch of rays has none"
                                                       : "it orders nothing where every ray is live"));
    o.sortRays = s;
  }
  if (auto v = takeFlag(args, "--order")) {
    if (*v != "tiles" && *v != "scanline") throw UsageError("--order: '" + *v + "' is neither tiles nor scanline");
    o.order = *v == "tiles" ? CameraRayOrder::Tiles : CameraRayOrder::Scanline;
  }
  if (auto v = takeFlag(args, "--repeat")) o.repeat = parseUint("--repeat", *v, 1, 1000);
  if (auto v = takeFlag(args, "--warmup")) o.warmup = parseUint("--warmup", *v, 0, 1000);
  if (auto v = takeFlag(args, "--seed")) o.seed = parseUint("--seed", *v, 0, 0xFFFFFFFFu);
  if (auto v = takeFlag(args, "--bounce-depth")) o.bounceDepth = parseUint("--bounce-depth", *v, 1, 8);
  o.sortEarlier = takeSwitch(args, "--sort-earlier");
  o.fetches = takeSwitch(args, "--fetches");
  if (auto v = takeFlag(args, "--check")) o.check = parseUint("--check", *v, 0, 1000000);
  if (auto v = takeFlag(args, "--csv")) o.csv = *v;
  if (auto v = takeFlag(args, "--export")) {
    if (v->empty()) throw UsageError("--export needs a folder");
    o.exportDir = *v;
  }
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--validate" || a.rfind("--validate=", 0) == 0) continue;
    if (std::find(kSharedFlags.begin(), kSharedFlags.end(), a) != kSharedFlags.end()) {
      ++i;  // its value (parseCommonOptions checks it)
      continue;
    }
    std::vector<std::string> known = kSharedFlags;
    known.insert(known.end(), kOwnFlags.begin(), kOwnFlags.end());
    throw UsageError(unknownOptionMessage(a, known));
  }
  const bool sizeGiven = std::find(args.begin(), args.end(), "--size") != args.end();
  const bool bvhGiven = std::find(args.begin(), args.end(), "--bvh") != args.end();
  o.common = parseCommonOptions(args);
  if (!sizeGiven) o.common.settings.width = 2048, o.common.settings.height = 1024;
  if (bvhGiven && !o.bvhs.empty()) throw UsageError("--bvh and --bvhs: give one of them");
  if (o.bvhs.empty()) o.bvhs = {o.common.settings.bvh};
  if (o.kinds.empty()) {
    o.kinds = {RayKind::Camera, RayKind::Bounce, RayKind::Shadow};
    if (o.sortRays) o.kinds.insert(o.kinds.begin() + 2, RayKind::BounceSorted);
  }
  if (!o.sortRays && std::find(o.kinds.begin(), o.kinds.end(), RayKind::BounceSorted) != o.kinds.end())
    throw UsageError("--kinds bounce-sorted needs --sort-rays STRATEGY: the key that sorts them");
  if (o.sortEarlier && (!o.sortRays || *o.sortRays == KeyStrategy::Oracle))
    throw UsageError("--sort-earlier needs --sort-rays with a key other than the oracle's (whose key needs the hits)");
  if (o.sortEarlier && o.bounceDepth < 2)
    throw UsageError("--sort-earlier needs --bounce-depth 2 or more: the camera rays are not sorted");
  if (o.fetches && std::find(o.bvhs.begin(), o.bvhs.end(), BvhLayout::Wide) != o.bvhs.end())
    throw UsageError("--fetches counts the pair-node traversal's reads: --bvhs binary or sbvh, not wide");
  return o;
}

}  // namespace raylab
