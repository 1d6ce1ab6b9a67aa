// What `raylab tracebench` is asked to trace and time: its flags, parsed. The ray kinds are declared here once
// (name and the traversal each takes); the table, the CSV and --kinds read them.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "app/cli_options.h"
#include "app/tracebench/trace_rays.h"
#include "shaders/hit_query_types.h"

namespace raylab {

enum class RayKind { Camera, Bounce, Shadow, BounceSorted };
struct RayKindInfo {
  RayKind kind;
  const char* name;
  uint32_t query;  // RL_HIT_QUERY_*: the traversal its rays take
};
// bounce-sorted: the bounce rays in the order --sort-rays' key gives them (the same rays).
inline constexpr RayKindInfo kRayKinds[] = {{RayKind::Camera, "camera", RL_HIT_QUERY_CLOSEST},
                                            {RayKind::Bounce, "bounce", RL_HIT_QUERY_CLOSEST},
                                            {RayKind::Shadow, "shadow", RL_HIT_QUERY_OCCLUDED},
                                            {RayKind::BounceSorted, "bounce-sorted", RL_HIT_QUERY_CLOSEST}};
inline const RayKindInfo& rayKindInfo(RayKind k) { return kRayKinds[static_cast<size_t>(k)]; }

struct TraceBenchOptions {
  CommonOptions common;  // scene, view, size, wide collapse, device, validation
  std::vector<BvhLayout> bvhs;  // --bvhs (or --bvh): every tree is timed in the same rounds
  std::vector<RayKind> kinds;  // default: camera, bounce (and bounce-sorted with --sort-rays), shadow
  std::optional<KeyStrategy> sortRays;  // --sort-rays: the key that orders bounce-sorted (grid flags as render)
  CameraRayOrder order = CameraRayOrder::Tiles;
  uint32_t repeat = 10, warmup = 3, seed = 1, check = 4096;
  uint32_t bounceDepth = 1;  // --bounce-depth: bounce and shadow rays leave the hits of this many bounces - 1
  bool sortEarlier = false;  // --sort-earlier: the earlier bounces traced in --sort-rays' order
  bool fetches = false;  // --fetches: each cell's reads counted by the CPU twin (warp_fetches.h)
  std::string csv;
  std::string exportDir;  // --export: the rays of each kind and the triangles as files (trace_rays.h)
};

// Throws UsageError for unknown flags and values, and for the render flags that mean nothing here.
TraceBenchOptions parseTraceBenchOptions(std::vector<std::string> args);
const char* traceBenchUsage();

}  // namespace raylab
