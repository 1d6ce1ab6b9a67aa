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
    "  --camera \"X Y Z TX TY TZ [fov D]\"  where the camera stands and looks at (scene units; the window's\n"
    "                         Scene panel shows and copies the current camera in this form); replaces --view\n"
    "  --time-budget S        accumulate frames for up to S seconds (wall clock), at most --frames of them\n"
    "                         (--frames defaults to unlimited then)\n";

void printRenderUsage(const std::string& error) {
  printUsageError("raylab render", error);
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

// Takes `--camera TEXT` out of `args`; empty when absent.
std::string takeCamera(std::vector<std::string>& args) {
  std::string text;
  for (size_t i = 0; i < args.size(); ++i) {
    if (args[i] != "--camera") continue;
    if (i + 1 >= args.size()) throw UsageError("--camera needs a value: \"X Y Z TX TY TZ [fov D]\"");
    text = args[i + 1];
    args.erase(args.begin() + static_cast<std::ptrdiff_t>(i), args.begin() + static_cast<std::ptrdiff_t>(i) + 2);
    --i;
  }
  return text;
}

// What a render was asked for, parsed and loaded.
struct RenderRequest {
  CommonOptions options;
  LoadedScene loaded;
  double budgetSeconds = 0.0;  // --time-budget; 0: none
  std::string learnedNote;     // --settings FILE.json whose length cache learned over more than its frames
};

// Parses the arguments and loads the scene; any error is reported as the command's exit code.
int parseRenderRequest(const std::vector<std::string>& givenArgs, RenderRequest& r) {
  std::vector<std::string> args = givenArgs;
  std::optional<Viewpoint> sidecarCamera;  // --settings FILE.json: a screenshot sidecar's settings and camera
  const int parsed = withCommandErrors(printRenderUsage, [&] {
    r.budgetSeconds = takeTimeBudget(args);
    const std::string cameraText = takeCamera(args);
    r.options = parseOptionsWithSettingsFile(args, &sidecarCamera, nullptr, &r.learnedNote);
    // With a time budget the frame count is only a ceiling: without --frames there is none.
    bool framesGiven = std::find(args.begin(), args.end(), "--frames") != args.end();
    bool sidecar = std::find(args.begin(), args.end(), "--settings") != args.end();  // its frames are the ceiling
    if (r.budgetSeconds > 0.0 && !framesGiven && !sidecar) r.options.settings.frames = SettingLimits::kMaxFrames;
    // A view without data would be an empty image: refuse it, saying what it needs.
    if (auto why = heatmapUnavailable(r.options.settings)) throw UsageError("--heatmap " + *why);
    r.loaded = loadSceneForSettings(r.options.settings);
    if (sidecarCamera) r.loaded.view = *sidecarCamera;
    if (!cameraText.empty()) {
      std::string error;
      std::optional<Viewpoint> v = cameraFromText(cameraText, r.loaded.view, &error);
      if (!v) throw UsageError("--camera: " + error);
      r.loaded.view = *v;
    }
    return int(kExitOk);
  });
  if (parsed == kExitOk && r.options.out.empty()) r.options.out = "raylab-render.png";
  return parsed;
}

// The frames of one render, summed.
struct RenderTotals {
  nlohmann::json frames = nlohmann::json::array();  // per frame, with --stats only
  double gpuMs = 0.0, wallMs = 0.0;
  uint64_t rays = 0;
  double raysPerSecond() const {
    const double seconds = (gpuMs > 0.0 ? gpuMs : wallMs) * 1e-3;
    return seconds > 0 ? rays / seconds : 0.0;
  }
};

// Renders --frames frames, or fewer when the time budget runs out first.
RenderTotals accumulate(PathTracer& tracer, const RenderRequest& r) {
  const Settings& s = r.options.settings;
  RenderTotals t;
  const auto started = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(); };
  if (r.budgetSeconds > 0.0 && s.frames >= SettingLimits::kMaxFrames)
    std::fprintf(stderr, "raylab: accumulating for %.3g s\n", r.budgetSeconds);
  else if (r.budgetSeconds > 0.0)
    std::fprintf(stderr, "raylab: accumulating for %.3g s (at most %u frames)\n", r.budgetSeconds, s.frames);
  for (uint32_t f = 0; f < s.frames && !(r.budgetSeconds > 0.0 && f > 0 && elapsed() >= r.budgetSeconds); ++f) {
    const FrameStats& st = tracer.renderFrame();
    t.gpuMs += st.frameMs;
    t.wallMs += st.wallMs;
    t.rays += st.raysTraced;
    if (!r.options.statsPath.empty()) t.frames.push_back(toJson(st));
  }
  return t;
}

// --stats FILE: the device, the scene and its BVHs, the settings and every frame.
void writeRenderStats(const VulkanContext& ctx, const PathTracer& tracer, const RenderRequest& r, const RenderTotals& t) {
  const GpuSceneData& scene = tracer.scene();
  nlohmann::json doc = {{"device", toJson(ctx.info())},
                        {"git_revision", gitRevision()},
                        {"scene", r.loaded.scene.name},
                        {"view", r.loaded.view.name},
                        {"triangles", scene.triangleCount()},
                        {"bvh_nodes", scene.bvhStats().nodeCount},
                        {"bvh_build_ms", scene.bvhStats().buildMs},
                        {"wide_bvh_nodes", scene.wideBvhStats().nodeCount},
                        {"wide_bvh_leaves", scene.wideBvhStats().leafCount},
                        {"wide_bvh_tree_bytes", scene.wideBvhStats().treeBytes()},
                        {"settings", toJson(r.options.settings)},
                        {"heatmap", toJson(tracer.stats().heatmap)},
                        {"total_gpu_ms", t.gpuMs},
                        {"total_wall_ms", t.wallMs},
                        {"rays_traced", t.rays},
                        {"rays_per_second", t.raysPerSecond()},
                        {"frames", t.frames}};
  writeFileChecked(r.options.statsPath, doc.dump(2) + "\n");  // throws WriteError: main reports it, exit 1
  std::printf("stats in %s\n", r.options.statsPath.c_str());
}

}  // namespace

int runRenderCommand(const std::vector<std::string>& givenArgs) {
  if (!givenArgs.empty() && (givenArgs[0] == "--help" || givenArgs[0] == "-h")) {
    std::printf("usage: raylab render [options]\n%s%s", commonOptionsHelp().c_str(), kRenderHelp);
    return kExitOk;
  }
  RenderRequest r;
  if (const int parsed = parseRenderRequest(givenArgs, r); parsed != kExitOk) return parsed;
  const Settings& s = r.options.settings;

  VulkanContext ctx(contextOptionsFor(r.options));
  for (const std::string& why : {unsupportedSettings(ctx.info(), s), pathsBeyondDevice(ctx.info(), s)})
    if (!why.empty()) {
      std::fprintf(stderr, "raylab render: %s\n", why.c_str());
      return kExitUsage;
    }
  PathTracer tracer(ctx, r.loaded.scene, s, r.loaded.view);
  tracer.setDetailedStats(!r.options.statsPath.empty());
  // A sidecar's moved camera has no name: viewpointLabel says where it stands instead.
  const std::string view = viewpointLabel(r.loaded.view);
  const std::string where = r.loaded.scene.name + (r.loaded.view.name.empty() ? ", " : "/") + view;  // temple/alley
  std::fprintf(stderr, "raylab: %s, %u triangles, BVH %u nodes in %.1f ms, wide BVH %u nodes (%s traversed)\n",
               where.c_str(), tracer.scene().triangleCount(), tracer.scene().bvhStats().nodeCount,
               tracer.scene().bvhStats().buildMs, tracer.scene().wideBvhStats().nodeCount, toString(s.bvh).c_str());

  if (!r.learnedNote.empty()) std::fprintf(stderr, "raylab render: note from the sidecar: %s\n", r.learnedNote.c_str());
  const RenderTotals totals = accumulate(tracer, r);
  // A heatmap carries its legend, and says headless what it shows (or why it shows nothing).
  const HeatmapStats& heat = tracer.stats().heatmap;
  const LegendImage image = withHeatmapLegend(tracer.readImage(), s.width, s.height, heat);
  writePng(r.options.out, image.width, image.height, image.rgba);  // throws WriteError: main reports it, exit 1
  if (!heat.view.empty()) std::printf("heatmap %s\n", heatmapLegendLine(heat).c_str());
  if (!heat.emptyReason.empty())
    std::fprintf(stderr, "raylab render: heatmap %s shows nothing: %s\n", heat.view.c_str(), heat.emptyReason.c_str());
  std::printf("wrote %s (%ux%u, %u spp, %s, %s, %s tracer) in %.2f s wall; %.3g rays/s\n",
              std::filesystem::absolute(r.options.out).string().c_str(), s.width, s.height,
              tracer.accumulatedFrames() * s.sppPerFrame, view.c_str(), toString(s.kernel).c_str(),
              toString(s.tracer).c_str(), totals.wallMs * 1e-3, totals.raysPerSecond());
  if (!r.options.statsPath.empty()) writeRenderStats(ctx, tracer, r, totals);
  if (ctx.validationErrors() > 0) {
    std::fprintf(stderr, "raylab: %u validation errors\n", ctx.validationErrors());
    return kExitValidation;
  }
  return kExitOk;
}

}  // namespace raylab
