// The renderer: a scene on the GPU, the wavefront (or megakernel) frame loop, progressive accumulation
// and tonemapping. Settings in, FrameStats out; the UI and the CLI use nothing else of it.
#pragma once

#include <memory>
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
  // Detailed statistics (per-path steps, prediction accuracy) cost readbacks; off for timed runs.
  void setDetailedStats(bool on) { detailedStats_ = on; }

  const FrameStats& stats() const { return stats_; }
  // The sort policy's model (stage times it learned) and the plan of the last recorded frame.
  const SortPolicyModel& sortPolicy() const { return sortPolicy_; }
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
  void allocate();
  void apply(const SettingsChange& change);
  void checkSupported(const Settings& settings) const;
  bool usesRt() const { return settings_.tracer == Tracer::Rt; }
  void recordFrameBlock(VkCommandBuffer cmd);
  void recordMegakernel(VkCommandBuffer cmd, const gpu::PathStagePush& push);
  void recordWavefront(VkCommandBuffer cmd, gpu::PathStagePush push);
  void recordStepsReadback(VkCommandBuffer cmd, uint32_t bounce);
  void recordCountersToHost(VkCommandBuffer cmd);
  void gatherCounters();
  uint32_t countedBounces() const;

  const VulkanContext& ctx_;
  Settings settings_;
  Viewpoint camera_;
  std::unique_ptr<GpuSceneData> scene_;
  std::unique_ptr<PathBuffers> buffers_;
  std::unique_ptr<PathSorter> pathSorter_;
  std::unique_ptr<HeatmapPass> heatmap_;
  std::unique_ptr<RtTracer> rt_;  // acceleration structures and rt pipelines, made when the rt tracer is first used
  ComputePipeline generate_, trace_, traceCounting_, shade_, accumulate_, tonemap_, megakernel_,
      megakernelCounting_;
  GpuTimer timer_;
  SortPolicyModel sortPolicy_;
  SortPlan framePlan_;  // which bounces the frame being recorded sorts after
  FrameStats stats_;
  uint32_t frameIndex_ = 0;
  bool detailedStats_ = false;
  std::vector<std::vector<uint32_t>> stepsPerBounce_;
  std::vector<GpuBuffer> stepsReadback_;
};

gpu::GpuCamera makeGpuCamera(const Viewpoint& v, uint32_t width, uint32_t height);

}  // namespace raylab
