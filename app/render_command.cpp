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
#include "app/camera_path/render_camera_path.h"
#include "app/render_totals.h"
#include "app/scene_setup.h"
#include "app/sidecar.h"
#include "renderer/heatmap/heatmap_rules.h"
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
    "  --camera-path FILE|builtin:NAME  render a moving camera: one image of --spp samples per path frame (the\n"
    "                         accumulation restarts every frame), --out is the last frame's, --stats has every\n"
    "                         frame with its camera and whether it is a cut; --frames caps the frames. FILE is\n"
    "                         JSON keyframes (README \"Camera paths\"); builtin:list lists the scene's paths\n"
    "  --camera \"X Y Z TX TY TZ [fov D]\"  where the camera stands and looks at (scene units; the window's\n"
    "                         Scene panel shows and copies the current camera in this form); replaces --view\n"
    "  --time-budget S        accumulate frames for up to S seconds (wall clock), at most --frames of them\n"
    "                         (--frames defaults to unlimited then)\n"
    "  --detail-every N       with --stats: the detailed figures (warp efficiency, prediction error, keys) on\n"
    "                         every Nth frame, from frame 0 (default 1: every frame; 0: none). Their GPU passes\n"
    "                         are the counters stage (instrument_ms), outside work_ms; frames without them show\n"
    "                         what they cost\n"
    "  --frame-digests        with --stats: each frame's \"radiance_digest\", a hash of its radiance's bits, to\n"
    "                         compare two renders frame by frame (the sorted-equals-unsorted invariant)\n";

void printRenderUsage(const std::string& error) {
  printUsageError("raylab render", error);
}

// What a render was asked for, parsed and loaded.
struct RenderRequest {
  CommonOptions options;
  LoadedScene loaded;
  double budgetSeconds = 0.0;  // --time-budget; 0: none
  uint32_t detailEvery = 1;    // --detail-every; 0: no detailed frame
  std::string learnedNote;     // --settings FILE.json whose length cache learned over more than its frames
  std::optional<PathRender> path;  // --camera-path
  bool frameDigests = false;       // --frame-digests
};

// Parses the arguments and loads the scene; any error is reported as the command's exit code.
int parseRenderRequest(const std::vector<std::string>& givenArgs, RenderRequest& r) {
  std::vector<std::string> args = givenArgs;
  std::optional<Viewpoint> sidecarCamera;  // --settings FILE.json: a screenshot sidecar's settings and camera
  const int parsed = withCommandErrors(printRenderUsage, [&] {
    if (auto budget = takeFlag(args, "--time-budget")) r.budgetSeconds = parseFloat("--time-budget", *budget, 0.001f, 86400.0f);
    const auto detailEvery = takeFlag(args, "--detail-every");
    if (detailEvery) r.detailEvery = parseUint("--detail-every", *detailEvery, 0, SettingLimits::kMaxFrames);
    r.frameDigests = takeSwitch(args, "--frame-digests");
    const std::string cameraText = takeFlag(args, "--camera").value_or("");
    const std::optional<std::string> pathSpec = takeFlag(args, "--camera-path");
    r.options = parseOptionsWithSettingsFile(args, &sidecarCamera, nullptr, &r.learnedNote);
    // With a time budget the frame count is only a ceiling: without --frames there is none.
    bool framesGiven = std::find(args.begin(), args.end(), "--frames") != args.end();
    bool sidecar = std::find(args.begin(), args.end(), "--settings") != args.end();  // its frames are the ceiling
    if (r.budgetSeconds > 0.0 && !framesGiven && !sidecar) r.options.settings.frames = SettingLimits::kMaxFrames;
    // A view without data would be an empty image: refuse it, saying what it needs.
    if (auto why = heatmapUnavailable(r.options.settings)) throw UsageError("--heatmap " + *why);
    if (detailEvery && r.options.statsPath.empty())
      throw UsageError("--detail-every needs --stats FILE.json: the detailed figures go there");
    if (r.frameDigests && r.options.statsPath.empty())
      throw UsageError("--frame-digests needs --stats FILE.json: the digests go there");
    r.loaded = loadSceneForSettings(r.options.settings);
    if (sidecarCamera) r.loaded.view = *sidecarCamera;
    if (!cameraText.empty()) {
      std::string error;
      std::optional<Viewpoint> v = cameraFromText(cameraText, r.loaded.view, &error);
      if (!v) throw UsageError("--camera: " + error);
      r.loaded.view = *v;
    }
    if (pathSpec) {
      const std::optional<uint32_t> framesCap = framesGiven ? std::optional<uint32_t>(r.options.settings.frames) : std::nullopt;
      r.path = preparePathRender(*pathSpec, r.loaded.scene, args, !cameraText.empty(), r.budgetSeconds > 0.0, framesCap);
      r.options.settings.frames = r.path->frames;  // what the stats' settings record
      r.loaded.view = cameraAt(r.path->path, 0, r.path->up).view;  // where the tracer starts (its grid, if clamped)
    }
    return int(kExitOk);
  });
  if (parsed == kExitOk && r.options.out.empty()) r.options.out = "raylab-render.png";
  return parsed;
}

// Renders --frames frames, or fewer when the time budget runs out first.
RenderTotals accumulate(PathTracer& tracer, const RenderRequest& r) {
  if (r.path) return renderAlongPath(tracer, *r.path, !r.options.statsPath.empty(), r.detailEvery, r.frameDigests);
  const Settings& s = r.options.settings;
  RenderTotals t;
  const auto started = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(); };
  if (r.budgetSeconds > 0.0 && s.frames >= SettingLimits::kMaxFrames)
    std::fprintf(stderr, "raylab: accumulating for %.3g s\n", r.budgetSeconds);
  else if (r.budgetSeconds > 0.0)
    std::fprintf(stderr, "raylab: accumulating for %.3g s (at most %u frames)\n", r.budgetSeconds, s.frames);
  const bool stats = !r.options.statsPath.empty();
  for (uint32_t f = 0; f < s.frames; ++f) {
    if (r.budgetSeconds > 0.0 && f > 0 && elapsed() >= r.budgetSeconds) {
      t.budgetSpent = true;
      break;
    }
    renderCountedFrame(tracer, f, stats, r.detailEvery, t, r.frameDigests);
  }
  return t;
}

// --stats FILE: the device, the scene and its BVHs, the settings and every frame.
void writeRenderStats(const VulkanContext& ctx, const PathTracer& tracer, const RenderRequest& r, const RenderTotals& t) {
  const GpuSceneData& scene = tracer.scene();
  nlohmann::json doc = {{"device", toJson(ctx.info())},
                        {"git_revision", gitRevision()},
                        {"scene", r.loaded.scene.name},
                        {"view", r.path ? r.path->path.name : r.loaded.view.name},
                        {"triangles", scene.triangleCount()},
                        {"bvh_nodes", scene.bvhStats().nodeCount},
                        {"bvh_build_ms", scene.bvhStats().buildMs},
                        {"bvh_sah_cost", scene.bvhStats().sahCost},
                        {"sbvh_nodes", scene.splitBvhStats().nodeCount},
                        {"sbvh_references", scene.splitBvhStats().references},
                        {"sbvh_sah_cost", scene.splitBvhStats().sahCost},
                        {"sbvh_build_ms", scene.splitBvhStats().buildMs},
                        {"wide_bvh_nodes", scene.wideBvhStats().nodeCount},
                        {"wide_bvh_leaves", scene.wideBvhStats().leafCount},
                        {"wide_bvh_tree_bytes", scene.wideBvhStats().treeBytes()},
                        {"settings", toJson(r.options.settings)},
                        {"heatmap", toJson(tracer.stats().heatmap)},
                        {"total_gpu_ms", t.gpuMs},
                        {"total_wall_ms", t.wallMs},
                        {"rays_traced", t.rays},
                        {"rays_per_second", t.raysPerSecond()},
                        {"rays_per_second_over", t.frameCount > 1 ? "frames 1 on (frame 0 warms up), GPU work time"
                                                                  : "frame 0 alone"},
                        {"detail_every", r.detailEvery},
                        {"stopped_by", t.budgetSpent ? "time budget" : "frames"},
                        {"frames", t.frames}};
  if (r.path) doc["camera_path"] = pathRenderJson(*r.path);
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
              tracer.accumulatedFrames() * s.sppPerFrame, viewpointLabel(tracer.camera()).c_str(), toString(s.kernel).c_str(),
              toString(s.tracer).c_str(), totals.wallMs * 1e-3, totals.raysPerSecond());
  if (!r.options.statsPath.empty()) writeRenderStats(ctx, tracer, r, totals);
  if (ctx.validationErrors() > 0) {
    std::fprintf(stderr, "raylab: %u validation errors\n", ctx.validationErrors());
    return kExitValidation;
  }
  return kExitOk;
}

}  // namespace raylab
