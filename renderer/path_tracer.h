// The renderer: a scene on the GPU, the wavefront (or megakernel) frame loop, progressive accumulation
// and tonemapping. Settings in, FrameStats out; the UI and the CLI use nothing else of it.
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "renderer/reorder/sort_policy.h"
#include "renderer/vk/command_counts.h"
#include "renderer/vk/compute_pipeline.h"
#include "renderer/vk/lazy_pipeline.h"
#include "renderer/frame_stats.h"
#include "renderer/frame_steps.h"
#include "renderer/gpu_scene.h"
#include "renderer/vk/gpu_timer.h"
#include "renderer/path_buffers.h"
#include "renderer/settings/settings.h"
#include "scenes/scene.h"

namespace raylab {

class VulkanContext;
class PathSorter;
class KeyStage;
class HeatmapPass;
class RtTracer;
class DetailStats;

class PathTracer {
 public:
  PathTracer(const VulkanContext& ctx, const Scene& scene, const Settings& settings, const Viewpoint& camera);
  // A second tracer of the same scene (the window's coarse preview): shares `sameScene`'s GPU scene (no second
  // BVH build or upload); `scene` must be the one `sameScene` was made from.
  PathTracer(const PathTracer& sameScene, const Scene& scene, const Settings& settings, const Viewpoint& camera);
  ~PathTracer();

  // Applies new settings: reallocates, restarts accumulation, resets caches and uploads key parameters
  // only where SettingsChange::between says it must.
  void applySettings(const Settings& settings);
  void setCamera(const Viewpoint& camera);
  // Starts accumulating from zero (the frame index too, so a restarted run repeats its samples).
  void restartAccumulation();
  // Starts the accumulation and the length cache from nothing, as a headless render of these settings starts:
  // the window's "restart learning" (a heatmap of learned lengths then re-renders from its sidecar).
  void restartLearning() {
    SettingsChange change;
    change.resetCache = change.keyParameters = change.resetAccumulation = true;
    apply(change);
  }
  const Settings& settings() const { return settings_; }
  const Viewpoint& camera() const { return camera_; }

  // Records one frame (all bounces, accumulate, tonemap) into `cmd`; finishFrame() after it completed.
  void recordFrame(VkCommandBuffer cmd);
  const FrameStats& finishFrame(double wallMs);
  // Records, submits and waits for one frame.
  const FrameStats& renderFrame();

  // A frame in steps, so a window can stay live while a frame renders: the frame's work is an ordered list
  // of steps (FrameStep: setup, generate, each bounce's trace, learn, heatmap, shade, keys, sort, reorder,
  // then accumulate, tonemap, counters), each over the whole frame, exactly what recordFrame records, so a
  // step computes what it computes in a whole frame (a sort sorts all of its bounce's live paths) and the
  // image, the stage times and the sort policy's inputs are those of a whole frame. recordSteps() records
  // the next `count` steps (at least one, at most what is left of the frame) into one submission;
  // finishSteps() after it completed adds their stage times and wall time to the frame's and returns the
  // whole frame's stats after its last step (else nullptr). Any change of settings or camera abandons a
  // partial frame (its steps are recorded again). Returns the steps recorded.
  uint32_t recordSteps(VkCommandBuffer cmd, uint32_t count);
  const FrameStats* finishSteps(double wallMs);
  // The steps of the frame not recorded yet (the whole frame's when none was: the frame's sort plan is made
  // then), and the GPU time of each step of the last finished submission, for a caller that budgets them.
  std::span<const FrameStep> pendingSteps();
  uint32_t frameSteps() const { return uint32_t(steps_.size()); }
  const std::vector<StepTime>& lastStepTimes() const { return lastStepTimes_; }
  uint32_t framePaths() const { return buffers_->pathCount; }

  // Detailed statistics (warp efficiency, prediction accuracy, distinct keys, cache occupancy): GPU
  // reductions timed as the "counters" stage (DetailStats), outside the frame's work; off for timed runs.
  void setDetailedStats(bool on);
  bool detailedStats() const { return detailedStats_; }

  const FrameStats& stats() const { return stats_; }
  // The sort policy's model (stage times it learned) and the plan of the last recorded frame.
  const SortPolicyModel& sortPolicy() const { return sortPolicy_; }
  // The same, to feed it a cost history (tests that need the auto policy's plan for a given history).
  SortPolicyModel& sortPolicy() { return sortPolicy_; }
  const SortPlan& sortPlan() const { return framePlan_; }
  uint32_t accumulatedFrames() const { return frameIndex_; }
  uint32_t width() const { return settings_.width; }
  uint32_t height() const { return settings_.height; }
  const GpuSceneData& scene() const { return *scene_; }
  const GpuBuffer& imageBuffer() const { return buffers_->image; }

  // The heatmap pass: the hovered pixel to read back (setProbe), and for tests its per-pixel values.
  HeatmapPass& heatmap() { return *heatmap_; }
  const HeatmapPass& heatmap() const { return *heatmap_; }
  // The key stage (grid, length cache) of the path sorter, for tests that check the heatmaps against it.
  const KeyStage& keyStage() const;

  std::vector<uint32_t> readImage() const;          // RGBA8 after tonemapping, row-major, top row first
  std::vector<glm::vec3> readRadiance() const;      // accumulated mean radiance per pixel (linear)

 private:
  PathTracer(const VulkanContext& ctx, const Scene& scene, std::shared_ptr<GpuSceneData> gpuScene,
             const Settings& settings, const Viewpoint& camera);
  void allocate();
  void apply(const SettingsChange& change);
  void checkSupported(const Settings& settings) const;
  bool usesRt() const { return settings_.tracer == Tracer::Rt; }
  void recordFrameBlock(VkCommandBuffer cmd);
  // The frame's steps (frame_steps.cpp): the plan, then the steps of the kernel in use.
  void buildSteps();
  void addStep(const char* name, int bounce, std::function<void(VkCommandBuffer)> record);
  void buildMegakernelSteps(const gpu::PathStagePush& push);
  void buildWavefrontSteps(gpu::PathStagePush push);
  // What bounce b records, decided once from the settings, the frame's sort plan and whether the last
  // sort's reorder is left to this bounce's trace.
  struct BouncePlan {
    bool sortedBefore = false;     // the rays traced now were keyed and sorted after the last bounce
    bool sortAfter = false;        // keys and a sort follow this bounce's shade
    bool keysInShade = false;      // shade writes the keys (Settings::fusesKeys)
    bool compacts = false;         // shade packs the live paths into the other state set
    bool learns = false;           // the length caches learn from this trace's hits
    bool fusesTraceShade = false;  // trace and shade in one dispatch
  };
  BouncePlan planBounce(uint32_t bounce, bool fusesGather) const;
  bool loopsFrom(uint32_t bounce, bool fusesGather) const;
  // Whether the traversal of bounce `bounce` (-1: the megakernel's) counts its steps: the frame's warp
  // statistics or a heatmap read them.
  bool countsSteps(int bounce) const;
  void buildBounceSteps(uint32_t bounce, gpu::PathStagePush& push, bool& fusesGather);
  void buildTraceStep(uint32_t bounce, const gpu::PathStagePush& push, bool gathers);
  void buildSortSteps(uint32_t bounce, bool keysInShade, gpu::PathStagePush& push, bool& fusesGather);
  void recordShade(VkCommandBuffer cmd, const gpu::PathStagePush& push, uint32_t bounce, bool fusesTraceShade);
  void buildEndSteps(const gpu::PathStagePush& push);
  void abandonFrame();
  void addStepStages(const std::vector<StageTime>& stages);
  const FrameStats& completeFrame();
  void recordCountersToHost(VkCommandBuffer cmd);
  void gatherCounters();
  void gatherDetails();
  uint32_t countedBounces() const;

  const VulkanContext& ctx_;
  Settings settings_;
  Viewpoint camera_;
  std::shared_ptr<GpuSceneData> scene_;
  std::unique_ptr<PathBuffers> buffers_;
  std::unique_ptr<PathSorter> pathSorter_;
  std::unique_ptr<HeatmapPass> heatmap_;
  std::unique_ptr<RtTracer> rt_;  // acceleration structures and rt pipelines, made when the rt tracer is first used
  std::unique_ptr<DetailStats> details_;
  ComputePipeline generate_, accumulate_, tonemap_;  // every frame records them
  // The variants the settings pick, each built on first use: trace.comp by [countSimt][fusesGather][countsSteps],
  // shade.comp by [compact][fusesTraceShade] (Settings::compaction, Settings::traceShade), megakernel.comp by
  // [countSimt][countsSteps][traversalOf(Settings::bvh)]. Steps are counted on the frames that read them (countsSteps).
  LazyPipeline trace_[2][2][2], shade_[2][2], megakernel_[2][2][2];
  LazyPipeline shadeLoop_[2];  // shade.comp's bounce loop (Settings::loopsBounces) by [traversalOf(Settings::bvh)]
  GpuTimer timer_;
  SortPolicyModel sortPolicy_;
  SortPlan framePlan_;  // which bounces the frame being recorded sorts after
  FrameStats stats_;
  uint32_t frameIndex_ = 0;
  // The frame being rendered in steps: its steps (empty: none built yet), the next one to record, those
  // the last submission recorded (and the timer scopes each began with), and the stage times and wall time
  // summed over the submissions completed so far.
  std::vector<FrameStep> steps_;
  uint32_t nextStep_ = 0;
  struct RecordedStep {
    uint32_t step, firstScope, endScope;
  };
  std::vector<RecordedStep> recorded_;
  std::vector<StepTime> lastStepTimes_;
  std::vector<StageTime> frameStages_;
  double frameGpuMs_ = 0.0, frameWallMs_ = 0.0;
  CommandTally frameCommands_;     // the commands the frame's steps recorded so far
  uint32_t frameSubmissions_ = 0;  // the submissions finished so far (finishSteps)
  bool detailedStats_ = false;
};

gpu::GpuCamera makeGpuCamera(const Viewpoint& v, uint32_t width, uint32_t height);

}  // namespace raylab
