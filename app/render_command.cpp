#include "app/render_command.h"

#include <chrono>
#include <filesystem>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>

#include "app/cli_options.h"
#include "app/scene_setup.h"
#include "app/sidecar.h"
#include "renderer/heatmap_rules.h"
#include "renderer/path_tracer.h"
#include "renderer/png_writer.h"
#include "renderer/stats_json.h"

namespace raylab {
namespace {

void printUsage(const std::string& error) {
  std::fprintf(stderr, "raylab render: %s\n\nusage: raylab render [options]\n%s", error.c_str(),
               commonOptionsHelp().c_str());
}

}  // namespace

int runRenderCommand(const std::vector<std::string>& args) {
  CommonOptions options;
  LoadedScene loaded;
  if (!args.empty() && (args[0] == "--help" || args[0] == "-h")) {
    std::printf("usage: raylab render [options]\n%s", commonOptionsHelp().c_str());
    return kExitOk;
  }
  std::optional<Viewpoint> sidecarCamera;  // --settings FILE.json: a screenshot sidecar's settings and camera
  try {
    options = parseOptionsWithSettingsFile(args, &sidecarCamera);
    // A view without data would be an empty image: refuse it, saying what it needs.
    if (auto why = heatmapUnavailable(options.settings)) throw UsageError("--heatmap " + *why);
    loaded = loadSceneForSettings(options.settings);
    if (sidecarCamera) loaded.view = *sidecarCamera;
  } catch (const UsageError& e) {
    printUsage(e.what());
    return kExitUsage;
  } catch (const SceneLoadError& e) {
    std::fprintf(stderr, "raylab: cannot load scene: %s\n", e.what());
    return kExitBadScene;
  }
  if (options.out.empty()) options.out = "raylab-render.png";
  const Settings& s = options.settings;

  VulkanContext ctx(contextOptionsFor(options));
  PathTracer tracer(ctx, loaded.scene, s, loaded.view);
  tracer.setDetailedStats(!options.statsPath.empty());
  std::fprintf(stderr, "raylab: %s/%s, %u triangles, BVH %u nodes in %.1f ms\n", loaded.scene.name.c_str(),
               loaded.view.name.c_str(), tracer.scene().triangleCount(), tracer.scene().bvhStats().nodeCount,
               tracer.scene().bvhStats().buildMs);

  nlohmann::json frames = nlohmann::json::array();
  double gpuMs = 0.0, wallMs = 0.0;
  uint64_t rays = 0;
  for (uint32_t f = 0; f < s.frames; ++f) {
    const FrameStats& st = tracer.renderFrame();
    gpuMs += st.frameMs;
    wallMs += st.wallMs;
    rays += st.raysTraced;
    if (!options.statsPath.empty()) frames.push_back(toJson(st));
  }
  writePng(options.out, s.width, s.height, tracer.readImage());
  double seconds = (gpuMs > 0.0 ? gpuMs : wallMs) * 1e-3;
  std::printf("wrote %s (%ux%u, %u spp, %s, %s) in %.2f s wall; %.3g rays/s\n",
              std::filesystem::absolute(options.out).string().c_str(), s.width,
              s.height, tracer.accumulatedFrames() * s.sppPerFrame, loaded.view.name.c_str(),
              toString(s.kernel).c_str(), wallMs * 1e-3, seconds > 0 ? rays / seconds : 0.0);

  if (!options.statsPath.empty()) {
    nlohmann::json doc = {{"device", toJson(ctx.info())},
                          {"git_revision", RAYLAB_GIT_REV},
                          {"scene", loaded.scene.name},
                          {"view", loaded.view.name},
                          {"triangles", tracer.scene().triangleCount()},
                          {"bvh_nodes", tracer.scene().bvhStats().nodeCount},
                          {"bvh_build_ms", tracer.scene().bvhStats().buildMs},
                          {"settings", toJson(s)},
                          {"total_gpu_ms", gpuMs},
                          {"total_wall_ms", wallMs},
                          {"rays_traced", rays},
                          {"rays_per_second", seconds > 0 ? rays / seconds : 0.0},
                          {"frames", frames}};
    std::ofstream(options.statsPath) << doc.dump(2) << "\n";
    std::printf("stats in %s\n", options.statsPath.c_str());
  }
  if (ctx.validationErrors() > 0) {
    std::fprintf(stderr, "raylab: %u validation errors\n", ctx.validationErrors());
    return kExitValidation;
  }
  return kExitOk;
}

}  // namespace raylab
