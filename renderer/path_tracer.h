// The renderer: a scene on the GPU, the wavefront (or megakernel) frame loop, progressive accumulation
// and tonemapping. Settings in, FrameStats out; the UI and the CLI use nothing else of it.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "renderer/reorder/sort_policy.h"
#include "renderer/vk/compute_pipeline.h"
#include "renderer/frame_stats.h"
#include "renderer/gpu_scene.h"
#include "renderer/vk/gpu_timer.h"
#include "renderer/path_buffers.h"
#include "renderer/settings.h"
#include "scenes/scene.h"

namespace raylab {

class VulkanContext;
class PathSorter;
class KeyStage;
class HeatmapPass;
class RtTracer;

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
  const Settings& settings() const { return settings_; }
  const Viewpoint& camera() const { return camera_; }

  // Records one frame (all bounces, accumulate, tonemap) into `cmd`; finishFrame() after it completed.
  void recordFrame(VkCommandBuffer cmd);
  const FrameStats& finishFrame(double wallMs);
  // Records, submits and waits for one frame.
  const FrameStats& renderFrame();

  // A frame in slices, one submission each, so a window can stay live while a frame renders: a slice is the
  // next `paths` path ids (clamped to what is left of the frame), generated, traced through every bounce
  // (sorted within the slice, which the invariant allows: a path's id, not its slot, picks its pixel, random
  // numbers and results entry) and shaded into results. The first slice clears the frame's counters; the
  // last one accumulates, tonemaps and copies the counters out, so the image after the last slice is bit for
  // bit the whole-frame render's. finishSlice() after each slice completed: it adds the slice's stage times
  // and wall time to the frame's, and returns the whole frame's stats after the last slice (else nullptr).
  // Any change of settings or camera abandons a partial frame (its paths are rendered again).
  // Returns the paths the slice holds.
  uint32_t recordSlice(VkCommandBuffer cmd, uint32_t paths);
  const FrameStats* finishSlice(double wallMs);
  // Paths of a whole frame, and the first path id of the next slice (0: the next slice starts a frame).
  uint32_t framePaths() const { return buffers_->pathCount; }
  uint32_t nextSlicePath() const { return sliceNext_; }
  // Heatmap views that depend on the whole frame's path order (sort-key ranks, warp efficiency) render in
  // one slice (recordSlice records the whole frame whatever it is asked for); other views and detailed
  // statistics gather each slice's part.
  bool needsWholeFrames() const;

  // Detailed statistics (per-path steps, prediction accuracy) cost readbacks; off for timed runs.
  void setDetailedStats(bool on);

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
  void recordFrameBlock(VkCommandBuffer cmd, uint32_t firstPath, uint32_t paths);
  void recordMegakernel(VkCommandBuffer cmd, const gpu::PathStagePush& push, PathRange slice);
  void recordWavefront(VkCommandBuffer cmd, gpu::PathStagePush push, PathRange slice);
  void addSliceStages(const std::vector<StageTime>& slice);
  const FrameStats& completeFrame();
  void recordStepsReadback(VkCommandBuffer cmd, uint32_t bounce, PathRange slice);
  void recordCountersToHost(VkCommandBuffer cmd);
  void gatherCounters();
  uint32_t countedBounces() const;

  const VulkanContext& ctx_;
  Settings settings_;
  Viewpoint camera_;
  std::shared_ptr<GpuSceneData> scene_;
  std::unique_ptr<PathBuffers> buffers_;
  std::unique_ptr<PathSorter> pathSorter_;
  std::unique_ptr<HeatmapPass> heatmap_;
  std::unique_ptr<RtTracer> rt_;  // acceleration structures and rt pipelines, made when the rt tracer is first used
  ComputePipeline generate_, trace_, traceCounting_, shade_, accumulate_, tonemap_, megakernel_,
      megakernelCounting_;
  // trace.comp's gathering variants (Settings::fusesGather), plain and counting, built on first use.
  std::optional<ComputePipeline> gatheringTrace_[2];
  const ComputePipeline& gatheringTrace(bool counting);
  // shade.comp's variants that compact (Settings::compaction) and trace first (Settings::traceShade),
  // indexed [compact][traceFirst] ([0][0] is shade_), built on first use.
  std::optional<ComputePipeline> shadeVariants_[2][2];
  const ComputePipeline& shadeVariant(bool compact, bool traceFirst);
  GpuTimer timer_;
  SortPolicyModel sortPolicy_;
  SortPlan framePlan_;  // which bounces the frame being recorded sorts after
  FrameStats stats_;
  uint32_t frameIndex_ = 0;
  // The frame being rendered in slices: the next slice's first path, the one recorded last (its end), and
  // the stage times and wall time summed over the slices completed so far.
  uint32_t sliceNext_ = 0, sliceEnd_ = 0;
  std::vector<StageTime> sliceStages_;
  double sliceGpuMs_ = 0.0, sliceWallMs_ = 0.0;
  bool detailedStats_ = false;
  std::vector<std::vector<uint32_t>> stepsPerBounce_;
  std::vector<GpuBuffer> stepsReadback_;
};

gpu::GpuCamera makeGpuCamera(const Viewpoint& v, uint32_t width, uint32_t height);

}  // namespace raylab
