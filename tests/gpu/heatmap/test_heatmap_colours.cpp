// The heatmap's GPU output against plain C++ references: every pixel's colour is what the host twins
// (renderer/heatmap/heatmap_colours.h) make of the value the GPU gathered; sort keys by cell decode to the cell the
// probe reports; ranks follow the keys' order; and "no path" and "no cache entry" are counted as a CPU
// lookup of the downloaded length cache and the trace's ray counters say.
#include <algorithm>
#include <bit>
#include <numeric>

#include <gtest/gtest.h>

#include "tests/gpu_test.h"
#include "renderer/heatmap/heatmap_pass.h"
#include "renderer/path_tracer.h"
#include "renderer/reorder/key_functions.h"
#include "renderer/reorder/key_stage.h"
#include "scenes/procedural.h"

namespace raylab::test {
namespace {

class HeatmapColoursGpu : public GpuTest {};

Settings heatSettings(HeatmapView view, KeyStrategy strategy) {
  Settings s;
  s.width = 64;
  s.height = 32;
  s.bounces = 3;
  s.heatmapBounce = 1;
  s.strategy = strategy;
  s.heatmap = view;
  return s;
}

// Each channel within one step of 255: the GPU may fuse or reorder the float operations of the ramp.
void expectColoursMatchReference(const PathTracer& tracer, const std::string& what) {
  const std::vector<uint32_t> image = tracer.readImage(), heat = tracer.heatmap().readValues();
  ASSERT_EQ(image.size(), heat.size());
  int mismatches = 0;
  for (size_t i = 0; i < image.size(); ++i) {
    const uint32_t want = heatmapPixelColour(tracer.heatmap().colouring(), heat[i]);
    for (int c = 0; c < 4; ++c) {
      const int a = int((image[i] >> (8 * c)) & 255u), b = int((want >> (8 * c)) & 255u);
      if (std::abs(a - b) > 1 && mismatches++ < 5)
        ADD_FAILURE() << what << ": pixel " << i << " channel " << c << " GPU " << a << " reference " << b
                      << " (heat 0x" << std::hex << heat[i] << ")";
    }
  }
  EXPECT_EQ(mismatches, 0) << what;
}

glm::uvec3 unpackCell(uint32_t c) {
  const uint32_t m = (1u << RL_HEAT_CELL_BITS) - 1;
  return {c & m, (c >> RL_HEAT_CELL_BITS) & m, c >> (2 * RL_HEAT_CELL_BITS)};
}

}  // namespace

TEST_F(HeatmapColoursGpu, SortKeyColoursAndCellsMatchTheReference) {
  Scene scene = makeTemple();
  const Viewpoint& view = *scene.findViewpoint("hall");
  PathTracer tracer(ctx(), scene, heatSettings(HeatmapView::SortKey, KeyStrategy::Fixed), view);
  for (KeyStrategy strategy : {KeyStrategy::Fixed, KeyStrategy::Average, KeyStrategy::TwoPoint,
                               KeyStrategy::OriginDirection, KeyStrategy::Direction, KeyStrategy::DeadLast})
    for (HeatmapKeyColour colour : {HeatmapKeyColour::Cell, HeatmapKeyColour::Hash}) {
      Settings s = heatSettings(HeatmapView::SortKey, strategy);
      s.heatmapKeyColour = colour;
      tracer.applySettings(s);
      tracer.renderFrame();
      const std::string what = toString(strategy) + "/" + toString(colour);
      expectColoursMatchReference(tracer, what);
      // The probe's cell is the GPU's decoding of the key; the host decodes the same key to the same cell.
      const std::vector<uint32_t> heat = tracer.heatmap().readValues(), probes = tracer.heatmap().readProbes();
      const gpu::GpuKeyGrid& grid = tracer.keyStage().grid().gpu;
      int keys = 0;
      for (size_t i = 0; i < heat.size(); ++i) {
        if (heat[i] == RL_HEAT_EMPTY) continue;
        ++keys;
        const uint32_t* p = &probes[i * RL_HEAT_PROBE_STRIDE];
        ASSERT_EQ(p[RL_HEAT_PROBE_KEY], heat[i]) << what;
        glm::uvec3 cells;
        const glm::uvec3 cell = keyCell(strategy, grid, heat[i], cells);
        const glm::uvec3 gpuCell = strategy == KeyStrategy::Direction
                                       ? glm::uvec3(p[RL_HEAT_PROBE_CELL] & 0xFFFFu, p[RL_HEAT_PROBE_CELL] >> 16, 0)
                                       : unpackCell(p[RL_HEAT_PROBE_CELL]);
        ASSERT_EQ(gpuCell, cell) << what << " key " << heat[i];
        ASSERT_EQ(p[RL_HEAT_PROBE_PATH] / s.sppPerFrame, i) << what << ": the probe's path is the pixel's";
      }
      EXPECT_EQ(uint32_t(keys), tracer.stats().heatmap.pixelsWithValue) << what;
      EXPECT_GT(keys, 0) << what;
    }
}

// Ranks: the sorted position of each pixel's key among the bounce's live keys. Ordered by rank, the keys
// (read from the probe) never decrease, and the ranks are distinct and below the live count.
TEST_F(HeatmapColoursGpu, RanksFollowTheKeysOrder) {
  Scene scene = makeTemple();
  for (KeyStrategy strategy : {KeyStrategy::Fixed, KeyStrategy::TwoPoint}) {
    Settings s = heatSettings(HeatmapView::SortKey, strategy);
    s.heatmapKeyColour = HeatmapKeyColour::Rank;
    PathTracer tracer(ctx(), scene, s, *scene.findViewpoint("alley"));
    tracer.renderFrame();
    expectColoursMatchReference(tracer, "rank " + toString(strategy));
    const std::vector<uint32_t> heat = tracer.heatmap().readValues(), probes = tracer.heatmap().readProbes();
    std::vector<std::pair<float, uint32_t>> rankKey;
    for (size_t i = 0; i < heat.size(); ++i)
      if (heat[i] != RL_HEAT_EMPTY) rankKey.push_back({std::bit_cast<float>(heat[i]), probes[i * RL_HEAT_PROBE_STRIDE + RL_HEAT_PROBE_KEY]});
    ASSERT_FALSE(rankKey.empty());
    std::sort(rankKey.begin(), rankKey.end());
    for (size_t k = 1; k < rankKey.size(); ++k) {
      ASSERT_LT(rankKey[k - 1].first, rankKey[k].first) << "ranks are distinct";
      ASSERT_LE(rankKey[k - 1].second, rankKey[k].second) << "a higher rank has a key at least as large";
    }
    EXPECT_EQ(rankKey.front().first, 0.0f);
    EXPECT_LT(rankKey.back().first, float(tracer.stats().bounces[1].rays)) << "rank below the live count";
    EXPECT_EQ(tracer.stats().heatmap.unit, "rank among the sorted keys");
  }
}

// Scalar views on linear and log scales, with the frame's range, a locked one and warp efficiency's 0..1.
TEST_F(HeatmapColoursGpu, ScalarViewsMatchTheReference) {
  Scene scene = makeTemple();
  PathTracer tracer(ctx(), scene, heatSettings(HeatmapView::TraversalSteps, KeyStrategy::Ema), *scene.findViewpoint("hall"));
  for (HeatmapView view : {HeatmapView::TraversalSteps, HeatmapView::WarpEfficiency, HeatmapView::CacheMean,
                           HeatmapView::CacheVariance, HeatmapView::CellHit})
    for (HeatmapScale scale : {HeatmapScale::Linear, HeatmapScale::Log})
      for (bool locked : {false, true}) {
        Settings s = heatSettings(view, KeyStrategy::Ema);
        s.heatmapScale = scale;
        s.heatmapRange = {locked, 4.0f, 30.0f};
        tracer.applySettings(s);
        tracer.renderFrame();
        const std::string what = toString(view) + "/" + toString(scale) + (locked ? "/locked" : "/frame");
        expectColoursMatchReference(tracer, what);
        const HeatmapStats& h = tracer.stats().heatmap;
        const bool scalar = view != HeatmapView::CellHit;
        if (scalar && locked) {
          EXPECT_EQ(h.min, 4.0) << what;
          EXPECT_EQ(h.max, 30.0) << what;
        } else if (view == HeatmapView::WarpEfficiency || view == HeatmapView::CellHit) {
          EXPECT_EQ(h.min, 0.0) << what << ": the natural range, never rescaled";
          EXPECT_EQ(h.max, 1.0) << what;
        } else {
          EXPECT_EQ(h.min, h.frameMin) << what;
          EXPECT_EQ(h.max, h.frameMax) << what;
        }
        EXPECT_EQ(h.scale, scalar ? toString(scale) : "linear") << what;
      }
}

// "No path" is a pixel whose path did not reach the bounce: the trace's own ray counter says how many did.
// "No cache entry" is a path whose (origin cell, octant) entry is missing or empty: the host looks each one
// up in the downloaded cache with key_functions' cacheEntry, and a value must be that entry's mean.
TEST_F(HeatmapColoursGpu, NoPathAndNoCacheEntryAreCountedAsTheCpuReference) {
  Scene scene = makeTemple();
  for (KeyStrategy strategy : {KeyStrategy::Gaussian, KeyStrategy::Average})
    for (const char* viewpoint : {"alley", "hall"}) {
      Settings s = heatSettings(HeatmapView::CacheMean, strategy);
      s.bounces = 2;  // the shown bounce is the last: nothing learns after the gather
      PathTracer tracer(ctx(), scene, s, *scene.findViewpoint(viewpoint));
      tracer.renderFrame();
      const std::string what = toString(strategy) + "@" + viewpoint;
      const HeatmapStats& h = tracer.stats().heatmap;
      const std::vector<uint32_t> heat = tracer.heatmap().readValues(), probes = tracer.heatmap().readProbes();
      const KeyStage& keys = tracer.keyStage();
      const LengthCache::Contents cache = keys.downloadCache();
      KeyEnv env;
      env.slotKeys = cache.slotKeys, env.slotValues = cache.slotValues, env.entries = cache.entries;
      uint32_t noPath = 0, noEntry = 0, values = 0;
      for (size_t i = 0; i < heat.size(); ++i) {
        if (heat[i] == RL_HEAT_EMPTY) {
          ++noPath;
          continue;
        }
        const uint32_t* p = &probes[i * RL_HEAT_PROBE_STRIDE];
        const uint32_t o = p[RL_HEAT_PROBE_OCTANT];
        const glm::vec3 dir(o & 1 ? -1.0f : 1.0f, o & 2 ? -1.0f : 1.0f, o & 4 ? -1.0f : 1.0f);
        const int32_t e = cacheEntry(keys.params().cache, env, keys.grid().gpu, unpackCell(p[RL_HEAT_PROBE_CELL]), dir);
        const bool empty = e < 0 || cache.entries[size_t(e)].count == 0;
        ASSERT_EQ(heat[i] == RL_HEAT_NO_VALUE, empty) << what << " pixel " << i << " entry " << e;
        if (empty) {
          ++noEntry;
        } else {
          ++values;
          ASSERT_EQ(std::bit_cast<float>(heat[i]), cache.entries[size_t(e)].mean) << what << " pixel " << i;
        }
      }
      EXPECT_EQ(noPath, uint32_t(heat.size()) - tracer.stats().bounces[1].rays) << what << ": one path a pixel (1 spp)";
      EXPECT_EQ(h.pixelsWithoutPath, noPath) << what;
      EXPECT_EQ(h.pixelsWithoutValue, noEntry) << what;
      EXPECT_EQ(h.pixelsWithValue, values) << what;
      EXPECT_GT(values, 0u) << what;
    }
}

// The hover readout: the probed pixel's value, path, key and cell come back with the frame, equal to the
// pixel's words in the full buffers; without a probe nothing is read back.
TEST_F(HeatmapColoursGpu, ProbeReadsTheHoveredPixel) {
  Scene scene = makeTemple();
  Settings s = heatSettings(HeatmapView::SortKey, KeyStrategy::Fixed);
  PathTracer tracer(ctx(), scene, s, *scene.findViewpoint("hall"));
  const glm::uvec2 pixel(40, 20);
  tracer.heatmap().setProbe(pixel);
  tracer.renderFrame();
  const size_t i = size_t(pixel.y) * s.width + pixel.x;
  const std::vector<uint32_t> heat = tracer.heatmap().readValues(), probes = tracer.heatmap().readProbes();
  const HeatmapProbe& q = tracer.stats().heatmap.probe;
  ASSERT_TRUE(q.valid);
  EXPECT_EQ(glm::uvec2(q.x, q.y), pixel);
  ASSERT_NE(heat[i], RL_HEAT_EMPTY) << "pick a pixel the hall's walls cover";
  EXPECT_EQ(q.state, "value");
  EXPECT_EQ(q.value, double(heat[i]));
  EXPECT_TRUE(q.hasPath && q.hasKey && q.hasCell);
  EXPECT_EQ(q.pathId, probes[i * RL_HEAT_PROBE_STRIDE + RL_HEAT_PROBE_PATH]);
  EXPECT_EQ(q.key, heat[i]);
  glm::uvec3 cells;
  EXPECT_EQ(q.cell, keyCell(KeyStrategy::Fixed, tracer.keyStage().grid().gpu, heat[i], cells));
  // A scalar view's probe: the value as a float, the ray origin's cell.
  s.heatmap = HeatmapView::TraversalSteps;
  tracer.applySettings(s);
  tracer.renderFrame();
  EXPECT_EQ(tracer.stats().heatmap.probe.value, double(std::bit_cast<float>(tracer.heatmap().readValues()[i])));
  EXPECT_EQ(tracer.stats().heatmap.probe.cellKind, "origin cell");
  tracer.heatmap().setProbe(std::nullopt);
  tracer.renderFrame();
  EXPECT_FALSE(tracer.stats().heatmap.probe.valid);
}

}  // namespace raylab::test
