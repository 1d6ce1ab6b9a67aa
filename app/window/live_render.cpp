#include "app/window/live_render.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "app/window/tiny_pass.h"
#include "app/window/wall_clock.h"
#include "renderer/path_tracer.h"
#include "renderer/vk/vk_context.h"

namespace raylab {
namespace {

// The preview's width and height are the render's divided by 2..16; 4 before anything was measured.
constexpr uint32_t kMinPreviewDivisor = 2, kMaxPreviewDivisor = 16, kFirstPreviewDivisor = 4;
// Smoothing of the measured costs: a new measurement counts half, so a setting that makes a step dearer
// is followed within two or three frames.
constexpr double kSmoothing = 0.5;
// The steps keep at least this share of the budget whatever the rest of the UI frame costs, so the render
// still progresses while the panels are busy.
constexpr double kMinStepShare = 0.25;

double smoothed(double previous, double measured) {
  return previous > 0.0 ? previous + kSmoothing * (measured - previous) : measured;
}

}  // namespace

LiveRender::LiveRender(const VulkanContext& ctx, double budgetMs)
    : ctx_(ctx), budgetMs_(budgetMs), tinyPass_(std::make_unique<TinyPass>(ctx)) {}

LiveRender::~LiveRender() = default;

void LiveRender::sceneChanged() {
  preview_.reset();
  showingPreview_ = false;
}

// The step's own measurement, else the mean of its kind at the other bounces (a bounce the sort policy
// sorts for the first time), else none.
double LiveRender::predictedMs(const FrameStep& step, uint32_t paths) const {
  if (auto it = msPerPath_.find({step.name, step.bounce}); it != msPerPath_.end()) return it->second * paths;
  double sum = 0.0;
  int n = 0;
  for (const auto& [key, perPath] : msPerPath_)
    if (key.first == step.name) sum += perPath, ++n;
  return n > 0 ? sum / n * paths : -1.0;
}

double LiveRender::wholeFrameMs(PathTracer& tracer) const {
  if (tracer.pendingSteps().size() != tracer.frameSteps()) return -1.0;  // part of a frame is done
  double ms = submitMs_;
  for (const FrameStep& step : tracer.pendingSteps()) {
    const double predicted = predictedMs(step, tracer.framePaths());
    if (predicted < 0.0) return -1.0;
    ms += predicted;
  }
  return ms;
}

// As many of the next steps as their predicted costs say fit `budgetMs`, at least one; a step nothing
// predicts is taken only first, and so measured alone.
uint32_t LiveRender::stepsThatFit(PathTracer& tracer, double budgetMs) const {
  double spent = submitMs_;
  uint32_t n = 0;
  for (const FrameStep& step : tracer.pendingSteps()) {
    const double predicted = predictedMs(step, tracer.framePaths());
    if (n > 0 && (predicted < 0.0 || spent + predicted > budgetMs)) break;
    spent += std::max(0.0, predicted);
    ++n;
  }
  return std::max(n, 1u);
}

void LiveRender::learnStepCosts(const PathTracer& tracer, double wallMs) {
  double gpuMs = 0.0;
  for (const StepTime& t : tracer.lastStepTimes()) {
    double& perPath = msPerPath_[{t.name, t.bounce}];
    perPath = smoothed(perPath, t.ms / tracer.framePaths());
    gpuMs += t.ms;
    if (t.ms > frameSlowest_.ms) frameSlowest_ = t;
  }
  submitMs_ = smoothed(submitMs_, std::max(0.0, wallMs - gpuMs));
}

RenderTurn LiveRender::turn(PathTracer& tracer, const Scene& scene, double otherWorkMs) {
  RenderTurn turn;
  if (previewDue_) {
    previewDue_ = false;
    showingPreview_ = false;
    // A frame that fits the budget is shown whole in this very UI frame: no preview needed.
    const double whole = wholeFrameMs(tracer);
    if (whole < 0.0 || whole > budgetMs_) {
      renderPreview(tracer, scene, &turn);
      return turn;  // the preview was this UI frame's render work
    }
  }
  const uint32_t want = stepsThatFit(tracer, std::max(kMinStepShare * budgetMs_, budgetMs_ - otherWorkMs));
  turn.frameSteps = tracer.frameSteps();
  const auto start = std::chrono::steady_clock::now();
  ctx_.submitAndWait([&](VkCommandBuffer cmd) {
    tinyPass_->record(cmd);
    turn.steps = tracer.recordSteps(cmd, want);
  });
  turn.renderMs = msSince(start);
  turn.frameDone = tracer.finishSteps(turn.renderMs);
  learnStepCosts(tracer, turn.renderMs);
  if (turn.frameDone) {
    slowestStep_ = frameSlowest_;
    frameSlowest_ = StepTime{};
    showingPreview_ = false;
    ++version_;
  }
  return turn;
}

// One whole frame of a small tracer of the same scene and camera: 1 sample per pixel, no sorting (the image
// is the same), no heatmap, the compute tracer, its size divided until it fits the budget.
void LiveRender::renderPreview(PathTracer& tracer, const Scene& scene, RenderTurn* turn) {
  const Settings& full = tracer.settings();
  uint32_t divisor = kFirstPreviewDivisor;
  const double whole = wholeFrameMs(tracer);
  const double perPath = previewMsPerPath_ > 0.0 ? previewMsPerPath_ : whole > 0.0 ? whole / tracer.framePaths() : 0.0;
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
