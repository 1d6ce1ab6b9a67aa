// The window's render work, sized so the UI stays live whatever a frame costs. Each UI frame gets about
// `budgetMs` of render work: the next slice of the render frame (PathTracer::recordSlice), as many paths as
// the measured milliseconds per path say fit, submitted apart from the panels. A frame that fits the budget
// is one slice (a fast GPU renders exactly as before). After a change that restarted the accumulation, when
// a whole frame does not fit, the first UI frame renders a coarse preview instead (a second, small tracer of
// the same scene: 1 sample, no sorting, the width and height divided until it fits the budget) and shows it
// until the full-resolution frame completes. Statistics stay those of whole frames: the preview's are never
// passed on, and a sliced frame's are its slices' sums.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "renderer/frame_stats.h"

namespace raylab {

class VulkanContext;
class PathTracer;
class GpuBuffer;
class TinyPass;
struct Scene;

// What one UI frame's render work did.
struct RenderTurn {
  double renderMs = 0.0;   // wall time of its render submissions
  uint32_t slicePaths = 0; // paths of the slice it rendered (0: none)
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
  // spends besides (panels, present), taken from the slice's budget so the whole UI frame keeps to it.
  RenderTurn turn(PathTracer& tracer, const Scene& scene, double otherWorkMs);
  ShownImage shown(const PathTracer& tracer) const;

 private:
  bool wholeFrameFits(const PathTracer& tracer) const;
  uint32_t slicePaths(const PathTracer& tracer, double budgetMs) const;
  void learnSliceCost(const PathTracer& tracer, uint32_t first, uint32_t paths, double ms);
  void renderPreview(const PathTracer& tracer, const Scene& scene, RenderTurn* turn);

  const VulkanContext& ctx_;
  double budgetMs_;
  double msPerPath_ = 0.0;         // slices' wall time per path, smoothed (0: not measured yet)
  // Wall time per path of each block of kCostBlock paths, from the last slice over it (0: not measured
  // since the last restart). Paths are in pixel order, so a slice over the sky costs a fraction of one over
  // the geometry: sizing the next slice from the last one's average overshot the budget at such borders.
  std::vector<double> blockMsPerPath_;
  double previewMsPerPath_ = 0.0;  // the same for previews
  std::unique_ptr<PathTracer> preview_;
  std::unique_ptr<TinyPass> tinyPass_;  // binds a 1x1 framebuffer before each render submission (tiny_pass.h)
  bool previewDue_ = false;
  bool showingPreview_ = false;
  uint64_t version_ = 1;
};

}  // namespace raylab
