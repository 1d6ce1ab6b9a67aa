// A representative subset of the renderer at a tiny size, for the GPU-assisted validation ctest
// (gpu_av.subset, RAYLAB_VALIDATE=gpu-av: every shader access through a device address is checked, which
// is too slow for the whole suite): every key strategy once, both sorts, compaction on and off, both
// fusions, trace and shade fused, the megakernel, every heatmap view, and the rt tracer where the device
// has it. In the ordinary suite it runs with synchronization validation like every other test.
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "renderer/heatmap/heatmap_rules.h"
#include "renderer/rt_tracer.h"
#include "renderer/vk/validation_layer.h"
#include "scenes/procedural.h"
#include "tests/gpu_test.h"
#include "tests/render_helpers.h"

namespace raylab::test {

class ValidationSubset : public GpuTest {
 protected:
  // Where the layer's GPU-assisted validation cannot instrument our shaders, say so (the gpu_av.subset
  // ctest reports itself skipped on this text) instead of crashing or passing without checks.
  void SetUp() override {
    GpuTest::SetUp();
    if (validationMode() == ValidationMode::GpuAssisted)
      if (std::string why = gpuAssistedUnavailable(); !why.empty()) GTEST_SKIP() << "GPU-AV unavailable: " << why;
  }
  // 2 frames (the second uses what the caches learned), 3 bounces (two sorted), 23x13 pixels.
  static Settings tiny() {
    Settings s = smallFrame(23, 13, 3);
    s.frames = 2;
    return s;
  }
  // One tracer per test, switched from variant to variant as the window switches settings: under GPU-AV every
  // pipeline the layer instruments is compiled anew (its shaders carry a fresh id, so no shader cache hits), and
  // a tracer per variant made this subset the longest test of CI (611 s). Switching rebuilds only what the
  // change needs: on Debian 13's lavapipe the subset's CPU time fell from 20 to 4.8 minutes.
  void render(const Settings& s, const std::string& what) {
    SCOPED_TRACE(what);
    if (!tracer_) tracer_ = std::make_unique<PathTracer>(ctx(), scene_, s, view_);
    else tracer_->applySettings(s);
    for (uint32_t f = 0; f < s.frames; ++f) tracer_->renderFrame();
    EXPECT_GT(moments(tracer_->readRadiance()).mean, 0.0) << what;
  }
  std::unique_ptr<PathTracer> tracer_;
  Scene scene_ = makeTemple();
  Viewpoint view_ = *scene_.findViewpoint("hall");
};

// Every strategy, each with one of the two sorts.
TEST_F(ValidationSubset, EveryKeyStrategyWithBothSorts) {
  int n = 0;
  for (KeyStrategy strategy : allKeyStrategies()) {
    Settings s = tiny();
    s.strategy = strategy;
    s.sort = n++ % 2 == 0 ? SortAlgorithm::Radix : SortAlgorithm::Bitonic;  // each sort meets half of them
    render(s, toString(strategy) + " " + toString(s.sort));
  }
}

TEST_F(ValidationSubset, CompactionFusionsAndTraceShade) {
  for (Compaction compaction : {Compaction::None, Compaction::Shade})
    for (Fusion fusion : {Fusion::None, Fusion::Keys, Fusion::Gather, Fusion::Both}) {
      Settings s = tiny();
      s.strategy = KeyStrategy::TwoPoint;
      s.compaction = compaction;
      s.fusion = fusion;
      render(s, toString(compaction) + " " + toString(fusion));
    }
  Settings fused = tiny();
  fused.traceShade = TraceShade::Fused;
  render(fused, "trace+shade fused");
  Settings loop = tiny();
  loop.traceShade = TraceShade::Loop;
  render(loop, "trace+shade loop");
  Settings megakernel = tiny();
  megakernel.kernel = Kernel::Megakernel;
  render(megakernel, "megakernel");
  // The other BVH layout's traversal (the default's is above) in the trace stage, shadow rays, the oracle key
  // and the megakernel.
  for (BvhLayout layout : allValues<BvhLayout>()) {
    if (layout == Settings{}.bvh) continue;
    Settings other = tiny();
    other.bvh = layout;
    other.strategy = KeyStrategy::Oracle;
    render(other, toString(layout) + " BVH, oracle key");
    other.kernel = Kernel::Megakernel;
    render(other, toString(layout) + " BVH megakernel");
  }
}

TEST_F(ValidationSubset, EveryHeatmapView) {
  for (HeatmapView view : allHeatmapViews()) {
    Settings s = tiny();
    s.strategy = view == HeatmapView::CacheVariance ? KeyStrategy::Gaussian : KeyStrategy::Average;
    s.heatmap = view;
    if (heatmapUnavailable(s)) continue;  // None, or a view these settings have no data for
    render(s, toString(view));
    EXPECT_FALSE(tracer_->readImage().empty()) << toString(view);
  }
}

TEST_F(ValidationSubset, RtTracer) {
  Settings s = tiny();
  s.tracer = Tracer::Rt;
  s.strategy = KeyStrategy::TwoPoint;
  if (std::string why = unsupportedSettings(ctx().info(), s); !why.empty()) GTEST_SKIP() << why;
  render(s, "rt wavefront");
  s.kernel = Kernel::Megakernel;
  s.strategy = KeyStrategy::None;
  render(s, "rt megakernel");
}

}  // namespace raylab::test
