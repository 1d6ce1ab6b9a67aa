#include "app/window/live_render.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "app/window/tiny_pass.h"
#include "renderer/path_tracer.h"
#include "renderer/vk/vk_context.h"

namespace raylab {
namespace {

// Slices are whole work groups of paths; the first slice, before any measurement, is small enough for any
// device (4096 paths: a few milliseconds on two lavapipe cores at 4 bounces).
constexpr uint32_t kSliceGranule = RL_PATH_GROUP_SIZE;
constexpr uint32_t kFirstSlicePaths = 4096;
// The preview's width and height are the render's divided by 2..16; 4 before anything was measured.
constexpr uint32_t kMinPreviewDivisor = 2, kMaxPreviewDivisor = 16, kFirstPreviewDivisor = 4;
// Smoothing of the measured milliseconds per path: a new measurement counts half, so a setting that makes
// paths dearer (more bounces) is followed within two or three UI frames.
constexpr double kSmoothing = 0.5;

double smoothed(double previous, double measured) {
  return previous > 0.0 ? previous + kSmoothing * (measured - previous) : measured;
}

double msSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

LiveRender::LiveRender(const VulkanContext& ctx, double budgetMs)
    : ctx_(ctx), budgetMs_(budgetMs), tinyPass_(std::make_unique<TinyPass>(ctx)) {}

LiveRender::~LiveRender() = default;

void LiveRender::sceneChanged() {
  preview_.reset();
  showingPreview_ = false;
}

bool LiveRender::wholeFrameFits(const PathTracer& tracer) const {
  return msPerPath_ > 0.0 && double(tracer.framePaths()) * msPerPath_ <= budgetMs_;
}

uint32_t LiveRender::slicePaths(const PathTracer& tracer) const {
  if (msPerPath_ <= 0.0) return std::min(kFirstSlicePaths, tracer.framePaths());
  const double fit = budgetMs_ / msPerPath_;
  if (fit >= double(tracer.framePaths())) return tracer.framePaths();
  return std::max(kSliceGranule, uint32_t(fit) / kSliceGranule * kSliceGranule);
}

RenderTurn LiveRender::turn(PathTracer& tracer, const Scene& scene) {
  RenderTurn turn;
  if (previewDue_) {
    previewDue_ = false;
    showingPreview_ = false;
    // A frame that fits the budget is shown whole in this very UI frame: no preview needed.
    if (!wholeFrameFits(tracer) && !tracer.needsWholeFrames()) {
      renderPreview(tracer, scene, &turn);
      return turn;  // the preview was this UI frame's render work
    }
  }
  const uint32_t want = slicePaths(tracer);
  const auto start = std::chrono::steady_clock::now();
  ctx_.submitAndWait([&](VkCommandBuffer cmd) {
    tinyPass_->record(cmd);
    turn.slicePaths = tracer.recordSlice(cmd, want);
  });
  turn.renderMs = msSince(start);
  msPerPath_ = smoothed(msPerPath_, turn.renderMs / turn.slicePaths);
  turn.frameDone = tracer.finishSlice(turn.renderMs);
  if (turn.frameDone) {
    showingPreview_ = false;
    ++version_;
  }
  return turn;
}

// One whole frame of a small tracer of the same scene and camera: 1 sample per pixel, no sorting (the image
// is the same), no heatmap, the compute tracer, its size divided until it fits the budget.
void LiveRender::renderPreview(const PathTracer& tracer, const Scene& scene, RenderTurn* turn) {
  const Settings& full = tracer.settings();
  uint32_t divisor = kFirstPreviewDivisor;
  const double perPath = previewMsPerPath_ > 0.0 ? previewMsPerPath_ : msPerPath_;
  if (perPath > 0.0) {
    const double pixels = double(full.width) * full.height;
    divisor = uint32_t(std::ceil(std::sqrt(pixels * perPath / budgetMs_)));
    divisor = std::clamp(divisor, kMinPreviewDivisor, kMaxPreviewDivisor);
  }
  Settings p = full;
  p.width = std::max(1u, full.width / divisor);
  p.height = std::max(1u, full.height / divisor);
  p.sppPerFrame = 1;
  p.strategy = KeyStrategy::None;
  p.heatmap = HeatmapView::None;
  p.countSimt = false;
  p.tracer = Tracer::Compute;
  p.ser = Ser::Off;
  if (!preview_) {
    preview_ = std::make_unique<PathTracer>(tracer, scene, p, tracer.camera());
  } else {
    preview_->applySettings(p);
    preview_->setCamera(tracer.camera());  // restarts its accumulation: a preview is always one fresh frame
  }
  const auto start = std::chrono::steady_clock::now();
  ctx_.submitAndWait([&](VkCommandBuffer cmd) {
    tinyPass_->record(cmd);
    preview_->recordFrame(cmd);
  });
  turn->renderMs = msSince(start);
  preview_->finishFrame(turn->renderMs);  // its statistics stay here: they are not the render's
  previewMsPerPath_ = smoothed(previewMsPerPath_, turn->renderMs / preview_->framePaths());
  turn->preview = true;
  turn->previewWidth = p.width, turn->previewHeight = p.height;
  showingPreview_ = true;
  ++version_;
}

ShownImage LiveRender::shown(const PathTracer& tracer) const {
  if (showingPreview_ && preview_)
    return {&preview_->imageBuffer(), preview_->width(), preview_->height(), version_};
  return {&tracer.imageBuffer(), tracer.width(), tracer.height(), version_};
}

}  // namespace raylab
