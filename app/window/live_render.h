// The window's render work, sized so the UI stays live whatever a frame costs. Each UI frame gets about
// `budgetMs` of render work: the next steps of the render frame (PathTracer::recordSteps: setup, generate,
// each bounce's trace, shade, keys, sort, ..., each over the whole frame), as many as the measured cost of
// each step (per step kind and bounce, smoothed) says fit, at least one, submitted apart from the panels. A
// step computes exactly what it does in a whole frame, so the image, the stage times and the sort policy's
// inputs are those of a headless render. A frame that fits the budget is one submission (a fast GPU renders
// exactly as before). A single step dearer than the budget holds its UI frame for its whole time: the
// window says so (RenderTurn::slowestStep). After a change that restarted the accumulation, when a whole
// frame does not fit, the first UI frame renders a coarse preview instead (a second, small tracer of the
// same scene: 1 sample, no sorting, the width and height divided until it fits the budget) and shows it
// until the full-resolution frame completes. The preview's statistics are never passed on.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <utility>

#include "renderer/frame_stats.h"
#include "renderer/frame_steps.h"

namespace raylab {

class VulkanContext;
class PathTracer;
class GpuBuffer;
class TinyPass;
struct Scene;

// What one UI frame's render work did.
struct RenderTurn {
  double renderMs = 0.0;   // wall time of its render submissions
  uint32_t steps = 0;      // frame steps it rendered (0: none)
  uint32_t frameSteps = 0; // steps of the render frame they belong to
  bool preview = false;    // it rendered a coarse preview
  uint32_t previewWidth = 0, previewHeight = 0;
  const FrameStats* frameDone = nullptr;  // the whole frame's statistics when one completed in it
};

// The pixels to show: the render's, or the preview's until the render has a frame since the last change.
struct ShownImage {
  const GpuBuffer* pixels = nullptr;  // RGBA8, row-major
  uint32_t width = 0, height = 0;
  uint64_t version = 0;  // changes whenever the pixels do (the presenter copies them only then)
};

class LiveRender {
 public:
  LiveRender(const VulkanContext& ctx, double budgetMs);
  ~LiveRender();

  // The render restarted its accumulation (camera or settings changed): the next turn previews.
  void restarted() { previewDue_ = true; }
  // The scene changed: the preview tracer of the old one goes.
  void sceneChanged();
  // This UI frame's render work on `tracer` (whose scene is `scene`). `otherWorkMs`: what the UI frame
  // spends besides (panels, present), taken from the steps' budget so the whole UI frame keeps to it.
  RenderTurn turn(PathTracer& tracer, const Scene& scene, double otherWorkMs);
  ShownImage shown(const PathTracer& tracer) const;
  // The dearest step of the last completed frame (its kind, bounce and GPU time): where it exceeds the
  // budget, the UI frame that renders it takes that long.
  const StepTime& slowestStep() const { return slowestStep_; }
  double budgetMs() const { return budgetMs_; }

 private:
  // Predicted milliseconds of a step of a frame of `paths` paths (< 0: nothing measured to predict from).
  double predictedMs(const FrameStep& step, uint32_t paths) const;
  double wholeFrameMs(PathTracer& tracer) const;  // < 0: not every step measured
  uint32_t stepsThatFit(PathTracer& tracer, double budgetMs) const;
  void learnStepCosts(const PathTracer& tracer, double wallMs);
  void renderPreview(PathTracer& tracer, const Scene& scene, RenderTurn* turn);

  const VulkanContext& ctx_;
  double budgetMs_;
  // GPU milliseconds per frame path of each step kind and bounce, smoothed (a frame of another size costs in
  // proportion), and a submission's wall time beyond its steps' GPU time (submit, wait, the tiny pass).
  std::map<std::pair<std::string, int>, double> msPerPath_;
  double submitMs_ = 0.0;
  StepTime slowestStep_, frameSlowest_;  // of the last completed frame, and of the one being rendered
  double previewMsPerPath_ = 0.0;  // the previews' wall time per path, smoothed (0: not measured yet)
  std::unique_ptr<PathTracer> preview_;
  std::unique_ptr<TinyPass> tinyPass_;  // binds a 1x1 framebuffer before each render submission (tiny_pass.h)
  bool previewDue_ = false;
  bool showingPreview_ = false;
  uint64_t version_ = 1;
};

}  // namespace raylab
