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

// Slices are whole work groups of paths; the first slice, before any measurement, is small enough for any
// device (4096 paths: a few milliseconds on two lavapipe cores at 4 bounces).
constexpr uint32_t kSliceGranule = RL_PATH_GROUP_SIZE;
constexpr uint32_t kFirstSlicePaths = 4096;
constexpr uint32_t kCostBlock = 1024;
// The preview's width and height are the render's divided by 2..16; 4 before anything was measured.
constexpr uint32_t kMinPreviewDivisor = 2, kMaxPreviewDivisor = 16, kFirstPreviewDivisor = 4;
// Smoothing of the measured milliseconds per path: a new measurement counts half, so a setting that makes
// paths dearer (more bounces) is followed within two or three UI frames.
constexpr double kSmoothing = 0.5;
// A slice keeps at least this share of the budget whatever the rest of the UI frame costs, so the render
// still progresses while the panels are busy.
constexpr double kMinSliceShare = 0.25;

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

bool LiveRender::wholeFrameFits(const PathTracer& tracer) const {
  return msPerPath_ > 0.0 && double(tracer.framePaths()) * msPerPath_ <= budgetMs_;
}

// As many paths from the next slice's first as the cost per path of their blocks (or, where not measured,
// the smoothed average) says fit `budgetMs`, in whole work groups.
uint32_t LiveRender::slicePaths(const PathTracer& tracer, double budgetMs) const {
  const uint32_t total = tracer.framePaths(), first = tracer.nextSlicePath();
  if (msPerPath_ <= 0.0) return std::min(kFirstSlicePaths, total);
  if (first == 0 && double(total) * msPerPath_ <= budgetMs) return total;
  double spent = 0.0;
  uint32_t end = first;
  while (end < total) {
    const size_t block = end / kCostBlock;
    const uint32_t blockEnd = std::min<uint32_t>(total, uint32_t(block + 1) * kCostBlock);
    const double cost = block < blockMsPerPath_.size() && blockMsPerPath_[block] > 0.0 ? blockMsPerPath_[block] : msPerPath_;
    const double all = double(blockEnd - end) * cost;
    if (spent + all > budgetMs) {
      end += uint32_t((budgetMs - spent) / cost);
      break;
    }
    spent += all;
    end = blockEnd;
  }
  if (end >= total) return total - first;
  return std::max(kSliceGranule, (end - first) / kSliceGranule * kSliceGranule);
}

void LiveRender::learnSliceCost(const PathTracer& tracer, uint32_t first, uint32_t paths, double ms) {
  const double perPath = ms / paths;
  msPerPath_ = smoothed(msPerPath_, perPath);
  blockMsPerPath_.resize((tracer.framePaths() + kCostBlock - 1) / kCostBlock, 0.0);
  for (uint32_t b = first / kCostBlock; b < blockMsPerPath_.size() && b * kCostBlock < first + paths; ++b)
    blockMsPerPath_[b] = perPath;
}

RenderTurn LiveRender::turn(PathTracer& tracer, const Scene& scene, double otherWorkMs) {
  RenderTurn turn;
  if (previewDue_) {
    previewDue_ = false;
    showingPreview_ = false;
    blockMsPerPath_.assign(blockMsPerPath_.size(), 0.0);  // another view or setting: other costs
    // A frame that fits the budget is shown whole in this very UI frame: no preview needed.
    if (!wholeFrameFits(tracer) && !tracer.needsWholeFrames()) {
      renderPreview(tracer, scene, &turn);
      return turn;  // the preview was this UI frame's render work
    }
  }
  const uint32_t want = slicePaths(tracer, std::max(kMinSliceShare * budgetMs_, budgetMs_ - otherWorkMs));
  const uint32_t first = tracer.nextSlicePath();
  const auto start = std::chrono::steady_clock::now();
  ctx_.submitAndWait([&](VkCommandBuffer cmd) {
    tinyPass_->record(cmd);
    turn.slicePaths = tracer.recordSlice(cmd, want);
  });
  turn.renderMs = msSince(start);
  learnSliceCost(tracer, tracer.needsWholeFrames() ? 0 : first, turn.slicePaths, turn.renderMs);
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
