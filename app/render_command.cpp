#include "app/render_command.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <cstdio>
#include <iostream>
#include <optional>

#include "app/cli_options.h"
#include "app/command_errors.h"
#include "app/fly_camera.h"
#include "app/heatmap_legend_image.h"
#include "app/scene_setup.h"
#include "app/sidecar.h"
#include "renderer/heatmap_rules.h"
#include "renderer/checked_write.h"
#include "renderer/path_tracer.h"
#include "renderer/png_writer.h"
#include "renderer/device_limits.h"
#include "renderer/rt_tracer.h"
#include "renderer/stats_json.h"
#include "renderer/git_revision.h"

namespace raylab {
namespace {

const char* const kRenderHelp =
    "  --time-budget S        accumulate frames for up to S seconds (wall clock), at most --frames of them\n"
    "                         (--frames defaults to unlimited then)\n";

void printRenderUsage(const std::string& error) {
  std::fprintf(stderr, "raylab render: %s\n\nusage: raylab render [options]\n%s%s", error.c_str(),
               commonOptionsHelp().c_str(), kRenderHelp);
}

// Takes `--time-budget S` out of `args` (the other flags are common ones); 0 when absent.
double takeTimeBudget(std::vector<std::string>& args) {
  double budget = 0.0;
  for (size_t i = 0; i < args.size(); ++i) {
    if (args[i] != "--time-budget") continue;
    if (i + 1 >= args.size()) throw UsageError("--time-budget needs a value");
    budget = parseFloat("--time-budget", args[i + 1], 0.001f, 86400.0f);
    args.erase(args.begin() + static_cast<std::ptrdiff_t>(i), args.begin() + static_cast<std::ptrdiff_t>(i) + 2);
    --i;
  }
  return budget;
}

}  // namespace

int runRenderCommand(const std::vector<std::string>& givenArgs) {
  CommonOptions options;
  LoadedScene loaded;
  if (!givenArgs.empty() && (givenArgs[0] == "--help" || givenArgs[0] == "-h")) {
    std::printf("usage: raylab render [options]\n%s%s", commonOptionsHelp().c_str(), kRenderHelp);
    return kExitOk;
  }
  std::vector<std::string> args = givenArgs;
  double budgetSeconds = 0.0;
  std::optional<Viewpoint> sidecarCamera;  // --settings FILE.json: a screenshot sidecar's settings and camera
  const int parsed = withCommandErrors(printRenderUsage, [&] {
    budgetSeconds = takeTimeBudget(args);
    options = parseOptionsWithSettingsFile(args, &sidecarCamera);
    // With a time budget the frame count is only a ceiling: without --frames there is none.
    bool framesGiven = std::find(args.begin(), args.end(), "--frames") != args.end();
    bool sidecar = std::find(args.begin(), args.end(), "--settings") != args.end();  // its frames are the ceiling
    if (budgetSeconds > 0.0 && !framesGiven && !sidecar) options.settings.frames = SettingLimits::kMaxFrames;
    // A view without data would be an empty image: refuse it, saying what it needs.
    if (auto why = heatmapUnavailable(options.settings)) throw UsageError("--heatmap " + *why);
    loaded = loadSceneForSettings(options.settings);
    if (sidecarCamera) loaded.view = *sidecarCamera;
    return int(kExitOk);
  });
  if (parsed != kExitOk) return parsed;
  if (options.out.empty()) options.out = "raylab-render.png";
  const Settings& s = options.settings;

  VulkanContext ctx(contextOptionsFor(options));
  if (std::string why = unsupportedSettings(ctx.info(), s); !why.empty()) {
    std::fprintf(stderr, "raylab render: %s\n", why.c_str());
    return kExitUsage;
  }
  if (std::string why = pathsBeyondDevice(ctx.info(), s); !why.empty()) {
    std::fprintf(stderr, "raylab render: %s\n", why.c_str());
    return kExitUsage;
  }
  PathTracer tracer(ctx, loaded.scene, s, loaded.view);
  tracer.setDetailedStats(!options.statsPath.empty());
  // A sidecar's moved camera has no name: viewpointLabel says where it stands instead.
  const std::string view = viewpointLabel(loaded.view);
  const std::string where = loaded.scene.name + (loaded.view.name.empty() ? ", " : "/") + view;  // temple/alley
  std::fprintf(stderr, "raylab: %s, %u triangles, BVH %u nodes in %.1f ms, wide BVH %u nodes (%s traversed)\n",
               where.c_str(), tracer.scene().triangleCount(), tracer.scene().bvhStats().nodeCount,
               tracer.scene().bvhStats().buildMs, tracer.scene().wideBvhStats().nodeCount, toString(s.bvh).c_str());

  nlohmann::json frames = nlohmann::json::array();
  double gpuMs = 0.0, wallMs = 0.0;
  uint64_t rays = 0;
  const auto started = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(); };
  if (budgetSeconds > 0.0)
    std::fprintf(stderr, "raylab: accumulating for %.3g s (at most %u frames)\n", budgetSeconds, s.frames);
  for (uint32_t f = 0; f < s.frames && !(budgetSeconds > 0.0 && f > 0 && elapsed() >= budgetSeconds); ++f) {
    const FrameStats& st = tracer.renderFrame();
    gpuMs += st.frameMs;
    wallMs += st.wallMs;
    rays += st.raysTraced;
    if (!options.statsPath.empty()) frames.push_back(toJson(st));
  }
  // A heatmap carries its legend, and says headless what it shows (or why it shows nothing).
  const HeatmapStats& heat = tracer.stats().heatmap;
  const LegendImage image = withHeatmapLegend(tracer.readImage(), s.width, s.height, heat);
  writePng(options.out, image.width, image.height, image.rgba);  // throws WriteError: main reports it, exit 1
  if (!heat.view.empty()) std::printf("heatmap %s\n", heatmapLegendLine(heat).c_str());
  if (!heat.emptyReason.empty())
    std::fprintf(stderr, "raylab render: heatmap %s shows nothing: %s\n", heat.view.c_str(), heat.emptyReason.c_str());
  double seconds = (gpuMs > 0.0 ? gpuMs : wallMs) * 1e-3;
  std::printf("wrote %s (%ux%u, %u spp, %s, %s, %s tracer) in %.2f s wall; %.3g rays/s\n",
              std::filesystem::absolute(options.out).string().c_str(), s.width,
              s.height, tracer.accumulatedFrames() * s.sppPerFrame, view.c_str(),
              toString(s.kernel).c_str(), toString(s.tracer).c_str(), wallMs * 1e-3, seconds > 0 ? rays / seconds : 0.0);

  if (!options.statsPath.empty()) {
    nlohmann::json doc = {{"device", toJson(ctx.info())},
                          {"git_revision", gitRevision()},
                          {"scene", loaded.scene.name},
                          {"view", loaded.view.name},
                          {"triangles", tracer.scene().triangleCount()},
                          {"bvh_nodes", tracer.scene().bvhStats().nodeCount},
                          {"bvh_build_ms", tracer.scene().bvhStats().buildMs},
                          {"wide_bvh_nodes", tracer.scene().wideBvhStats().nodeCount},
                          {"wide_bvh_leaves", tracer.scene().wideBvhStats().leafCount},
                          {"wide_bvh_tree_bytes", tracer.scene().wideBvhStats().treeBytes()},
                          {"settings", toJson(s)},
                          {"heatmap", toJson(heat)},
                          {"total_gpu_ms", gpuMs},
                          {"total_wall_ms", wallMs},
                          {"rays_traced", rays},
                          {"rays_per_second", seconds > 0 ? rays / seconds : 0.0},
                          {"frames", frames}};
    writeFileChecked(options.statsPath, doc.dump(2) + "\n");  // throws WriteError: main reports it, exit 1
    std::printf("stats in %s\n", options.statsPath.c_str());
  }
  if (ctx.validationErrors() > 0) {
    std::fprintf(stderr, "raylab: %u validation errors\n", ctx.validationErrors());
    return kExitValidation;
  }
  return kExitOk;
}

}  // namespace raylab
