#include "app/bench/bench_measure.h"

#include <algorithm>
#include <chrono>

#include "renderer/image_metrics.h"
#include "renderer/stages.h"
#include "renderer/stats_json.h"

namespace raylab {

namespace {

// Whether the next frame's plan measures (auto's warm-up, exploration or probe) rather than decides.
bool nextPlanMeasures(const PathTracer& tracer, const Settings& s) {
  return s.sorts() && tracer.sortPolicy().plan(s.sortPolicy, s.bounces).measuring;
}

}  // namespace

std::vector<double> measureErrorCurve(PathTracer& tracer, const Settings& settings, uint32_t frames,
                                      const std::vector<glm::vec3>& reference) {
  Settings plain = settings;
  plain.kernel = Kernel::Wavefront;
  plain.strategy = KeyStrategy::None;
  tracer.setDetailedStats(false);
  tracer.applySettings(plain);
  tracer.restartAccumulation();
  std::vector<double> curve;
  for (uint32_t f = 0; f < frames; ++f) {
    tracer.renderFrame();
    curve.push_back(relativeMse(tracer.readRadiance(), reference));
  }
  return curve;
}

void TimedFrames::add(const FrameStats& st, double ms) {
  frame.push_back(ms);
  wall.push_back(st.wallMs);
  rays += st.raysTraced;
  total += ms;
  std::map<std::string, double> perStage, perBounce;
  double later = 0.0, camera = 0.0;
  for (const StageTime& s : st.stages) {
    if (const StageInfo* info = findStage(s.stage); info && info->role == StageRole::Instrument) continue;
    perStage[s.stage] += s.ms;
    if (s.bounce >= 0) perBounce[s.stage + "@" + std::to_string(s.bounce)] += s.ms;
    if (s.stage == "trace" && s.bounce >= 1) later += s.ms, tracedLater = true;
    if (s.stage == "trace" && s.bounce == 0) camera += s.ms;
  }
  uint64_t laterRays = 0;
  for (size_t b = 1; b < st.bounces.size(); ++b) laterRays += st.bounces[b].rays;
  if (camera > 0.0 && !st.bounces.empty()) cameraRate.push_back(st.bounces[0].rays / (camera * 1e-3));
  if (later > 0.0) bounceRate.push_back(laterRays / (later * 1e-3));
  for (const auto& [name, v] : perStage) stages[name].push_back(v);
  for (const auto& [name, v] : perBounce) bounceStages[name].push_back(v);
  traceLater.push_back(later);
  commands = st.commands;
  submissions = st.submissions;
}

void TimedFrames::fillInto(CellResult& r) const {
  r.frameMs = spreadOf(frame);
  r.wallMs = spreadOf(wall);
  if (tracedLater) r.traceAfterFirstMs = spreadOf(traceLater);
  if (!cameraRate.empty()) r.traceCameraRaysPerSecond = spreadOf(cameraRate);
  if (!bounceRate.empty()) r.traceBounceRaysPerSecond = spreadOf(bounceRate);
  for (const auto& [name, v] : stages) r.stageMs[name] = spreadOf(v);
  for (const auto& [name, v] : bounceStages) r.stageBounceMs[name] = spreadOf(v);
  r.raysPerSecond = total > 0.0 ? rays / (total * 1e-3) : 0.0;
  r.commands = commands;
  r.submissions = submissions;
}

std::string sortPlanText(const std::vector<bool>& sortAfter) {
  std::string text;
  for (size_t k = 0; k < sortAfter.size(); ++k) text += k + 1 == sortAfter.size() ? '-' : sortAfter[k] ? 'Y' : 'N';
  return text;
}

void warmUpFrames(PathTracer& tracer, uint32_t warmup) {
  auto start = std::chrono::steady_clock::now();
  for (uint32_t f = 0; f < warmup || std::chrono::steady_clock::now() - start < std::chrono::milliseconds(500); ++f)
    tracer.renderFrame();
}

CellResult measureCell(PathTracer& tracer, const Settings& settings, uint32_t warmup, uint32_t timed,
                       const std::vector<glm::vec3>& reference, const std::vector<double>& errorCurve,
                       bool detailFrame) {
  CellResult r;
  tracer.setDetailedStats(false);
  tracer.applySettings(settings);
  warmUpFrames(tracer, warmup);
  // auto is timed from the frame its plan stops exploring: timed while it explores, a cell of 8.4M paths read
  // the unsorted arm's time while its plan sorted every bounce (H200, issue 34).
  // (A probe frame measures too: timing then starts after it.)
  for (uint32_t settle = 0; nextPlanMeasures(tracer, settings) && settle < kMaxSettleFrames; ++settle) tracer.renderFrame();
  if (settings.sorts() && settings.sortPolicy == SortPolicy::Auto) {
    r.policyFramesBeforeTiming = tracer.sortPolicy().framesSeen();
    r.policySettled = !nextPlanMeasures(tracer, settings);
  }
  tracer.restartAccumulation();

  TimedFrames frames;
  for (uint32_t f = 0; f < timed; ++f) {
    const FrameStats& st = tracer.renderFrame();
    frames.add(st, st.frameMs > 0.0 ? st.frameMs : st.wallMs);
  }
  frames.fillInto(r);
  if (!reference.empty()) r.finalRelMse = relativeMse(tracer.readRadiance(), reference);
  for (size_t k = 0; k < errorCurve.size(); ++k) {
    r.errorCurveMs.push_back(double(k + 1) * r.frameMs.median);
    r.errorCurveRelMse.push_back(errorCurve[k]);
  }

  // The plan the policy decided on: a probe or exploration frame describes the arm it measures, not the
  // policy (the counting frame of an auto cell on lavapipe was one, and showed the unsorted coherence).
  // Untimed frames until the next plan decides; the counting frame renders that plan, since counting frames
  // are not fed back to the policy (PathTracer).
  for (uint32_t extra = 0; nextPlanMeasures(tracer, settings) && extra < kMaxSettleFrames; ++extra) tracer.renderFrame();
  if (settings.sorts()) r.sortedAfter = tracer.sortPolicy().plan(settings.sortPolicy, settings.bounces).sortAfter;

  if (!detailFrame) return r;
  // Counting and readbacks slow the frame down, so they get their own frame, outside the timed ones.
  Settings counting = settings;
  counting.countSimt = true;
  tracer.applySettings(counting);
  tracer.setDetailedStats(true);
  r.detailed = tracer.renderFrame();
  r.detailMeasured = true;
  tracer.setDetailedStats(false);
  tracer.applySettings(settings);
  return r;
}

SceneFacts sceneFactsOf(const GpuSceneData& scene, double sceneLoadMs, double tracerSetupMs) {
  SceneFacts f;
  f.triangles = scene.triangleCount();
  f.bvhNodes = scene.bvhStats().nodeCount;
  f.bvhBytes = f.bvhNodes * sizeof(gpu::BvhNode) + f.triangles * sizeof(gpu::GpuTriangle);
  f.wideBvhNodes = scene.wideBvhStats().nodeCount;
  f.wideBvhBytes = scene.wideBvhStats().treeBytes() + f.triangles * sizeof(gpu::GpuTriangle);
  f.sceneBytes = scene.memoryBytes();
  f.bvhBuildMs = scene.bvhStats().buildMs;
  f.sbvhReferences = scene.splitBvhStats().references;
  f.sbvhBuildMs = scene.splitBvhStats().buildMs;
  f.sceneLoadMs = sceneLoadMs;
  f.tracerSetupMs = tracerSetupMs;
  return f;
}

nlohmann::json toJson(const SceneFacts& f) {
  return {{"triangles", f.triangles},           {"bvh_nodes", f.bvhNodes},
          {"bvh_bytes", f.bvhBytes},            {"scene_bytes", f.sceneBytes},
          {"bvh_build_ms", f.bvhBuildMs},       {"scene_load_ms", f.sceneLoadMs},
          {"tracer_setup_ms", f.tracerSetupMs}, {"wide_bvh_nodes", f.wideBvhNodes},
          {"wide_bvh_bytes", f.wideBvhBytes},   {"sbvh_references", f.sbvhReferences},
          {"sbvh_build_ms", f.sbvhBuildMs}};
}

nlohmann::json toJson(const RunFacts& f) {
  return {{"empty_dispatch_us", f.emptyDispatchUs ? nlohmann::json(*f.emptyDispatchUs) : nlohmann::json(nullptr)}};
}

std::optional<double> fixedCostMs(const CommandCounts& commands, const RunFacts& facts) {
  if (!facts.emptyDispatchUs) return std::nullopt;
  return commands.dispatches() * *facts.emptyDispatchUs * 1e-3;
}

nlohmann::json toJson(const CellResult& r) {
  auto spread = [](const Spread& s) { return toJson(s); };
  nlohmann::json stages;
  for (const auto& [name, s] : r.stageMs) stages[name] = spread(s);
  nlohmann::json bounceStages = nlohmann::json::object();
  for (const auto& [name, s] : r.stageBounceMs) bounceStages[name] = s.median;
  return {{"frame_ms", spread(r.frameMs)},
          {"wall_ms", spread(r.wallMs)},
          {"trace_after_first_ms", r.traceAfterFirstMs ? spread(*r.traceAfterFirstMs) : nlohmann::json(nullptr)},
          {"stage_ms", stages},
          {"stage_bounce_ms", bounceStages},
          {"sorted_after", r.sortedAfter},
          {"rays_per_second", r.raysPerSecond},
          {"trace_camera_rays_per_second",
           r.traceCameraRaysPerSecond ? spread(*r.traceCameraRaysPerSecond) : nlohmann::json(nullptr)},
          {"trace_bounce_rays_per_second",
           r.traceBounceRaysPerSecond ? spread(*r.traceBounceRaysPerSecond) : nlohmann::json(nullptr)},
          {"error_curve_ms", r.errorCurveMs},
          {"error_curve_rel_mse", r.errorCurveRelMse},
          {"final_rel_mse", r.finalRelMse ? nlohmann::json(*r.finalRelMse) : nlohmann::json(nullptr)},
          {"policy_frames_before_timing",
           r.policyFramesBeforeTiming ? nlohmann::json(*r.policyFramesBeforeTiming) : nlohmann::json(nullptr)},
          {"policy_settled", r.policySettled},
          {"camera_path", r.path ? nlohmann::json{{"name", r.path->name},
                                                  {"frames", r.path->frames},
                                                  {"total_ms", r.path->totalMs},
                                                  {"mean_ms", r.path->meanMs}}
                                 : nlohmann::json(nullptr)},
          {"commands", commandsJson(r.commands, r.submissions)},
          {"detailed_frame", r.detailMeasured ? toJson(r.detailed) : nlohmann::json(nullptr)}};
}

}  // namespace raylab
