// The heatmap's colour mappings on the host (renderer/heatmap/heatmap_colours.h, twins of heatmap_colours.glsl):
// a key decodes to the cell the key function encoded, cell colours follow position, the log scale spreads
// decades evenly, and the legend burned into saved PNGs has its bar, labels and swatches.
#include <algorithm>
#include <random>

#include <gtest/gtest.h>

#include "app/cli_options.h"
#include "app/heatmap_legend_image.h"
#include "renderer/heatmap/heatmap_colours.h"
#include "renderer/reorder/key_functions.h"
#include "renderer/reorder/key_grid.h"
#include "renderer/settings/settings_validation.h"
#include "renderer/stats_json.h"

namespace raylab {
namespace {

gpu::GpuKeyParams paramsFor(glm::uvec3 cells) {
  Bounds b;
  b.min = glm::vec3(0);
  b.max = glm::vec3(10, 4, 6);
  Settings s;
  s.grid.automatic = false;
  s.grid.cells = cells;
  gpu::GpuKeyParams p{};
  p.grid = makeKeyGrid(b, {}, s).gpu;
  p.fixedLength = 5.0f;
  p.cache.lengthMax = 20.0f;
  return p;
}

// The top `keep` bits of a cell coordinate of `bits` bits (what a key that dropped levels still holds).
uint32_t topBits(uint32_t v, uint32_t bits, uint32_t dropped) { return dropped >= bits ? 0 : (v >> dropped) << dropped; }

}  // namespace

// keyCell inverts each key function: point keys give back the end point's cell, two-point keys its end cell
// (to the levels the 23 kept bits hold), origin-direction keys the origin cell, direction keys the
// octahedral cell.
TEST(HeatmapColours, KeyCellDecodesWhatEachKeyFunctionEncoded) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::normal_distribution<float> g(0.0f, 1.0f);
  for (glm::uvec3 cellsPerAxis : {glm::uvec3(1), glm::uvec3(7, 3, 100), glm::uvec3(64, 26, 38), glm::uvec3(1024)}) {
    const gpu::GpuKeyParams p = paramsFor(cellsPerAxis);
    for (int n = 0; n < 400; ++n) {
      const glm::vec3 o = glm::vec3(u(rng) * 10, u(rng) * 4, u(rng) * 6);
      const glm::vec3 d = glm::normalize(glm::vec3(g(rng), g(rng), g(rng)) + glm::vec3(1e-6f));
      const KeyPath path{o, d, uint32_t(n), 2.5f};
      for (KeyStrategy k : {KeyStrategy::Fixed, KeyStrategy::Origin, KeyStrategy::Oracle, KeyStrategy::TwoPoint,
                            KeyStrategy::OriginDirection, KeyStrategy::Direction}) {
        float len = 0;
        const uint32_t key = computeKey(strategyId(k), p, KeyEnv{}, path, 1, len);
        glm::uvec3 cells;
        const glm::uvec3 got = keyCell(k, p.grid, key, cells);
        const std::string what = toString(k) + " key " + std::to_string(key);
        if (k == KeyStrategy::Direction) {
          const uint32_t bitsU = (p.grid.gridBits + 1) / 2, bitsV = p.grid.gridBits / 2;
          EXPECT_EQ(cells, glm::uvec3(1u << bitsU, 1u << bitsV, 1u)) << what;
          EXPECT_EQ(glm::uvec2(got), octahedralCell(d, bitsU, bitsV)) << what;
          continue;
        }
        EXPECT_EQ(cells, p.grid.cells) << what;
        if (k == KeyStrategy::TwoPoint) {
          const glm::uvec3 end = cellOf(p.grid, endPoint(path, len));
          // 2 * gridBits interleaved, the finest levels dropped to keep 23: whole levels of all six axes.
          const uint32_t total = 2 * p.grid.gridBits;
          const uint32_t dropped = total > RL_KEY_TWO_POINT_BITS ? total - RL_KEY_TWO_POINT_BITS : 0;
          for (int a = 0; a < 3; ++a) {
            // An axis loses as many levels as are dropped among the finest ones it takes part in; check the
            // bits no drop can touch (those above the dropped count, a safe bound).
            const uint32_t lost = std::min(p.grid.bits[a], dropped);
            EXPECT_EQ(topBits(got[a], p.grid.bits[a], lost), topBits(end[a], p.grid.bits[a], lost)) << what << " axis " << a;
          }
        } else if (k == KeyStrategy::OriginDirection) {
          if (p.grid.gridBits + 2 * p.grid.maxAxisBits <= RL_KEY_MAX_SPATIAL_BITS) {
            EXPECT_EQ(got, cellOf(p.grid, o)) << what;
          }
        } else {
          const glm::vec3 point = k == KeyStrategy::Origin ? o : endPoint(path, len);
          EXPECT_EQ(got, cellOf(p.grid, point)) << what;
        }
      }
    }
  }
}

TEST(HeatmapColours, DeinterleaveInvertsInterleave) {
  std::mt19937 rng(9);
  const uint32_t w[6] = {5, 3, 7, 5, 3, 7};
  for (int n = 0; n < 1000; ++n) {
    uint32_t c[6], back[6];
    for (int k = 0; k < 6; ++k) c[k] = rng() & ((1u << w[k]) - 1);
    deinterleaveBits(interleaveBits(c, w, 6, 32), w, 6, 32, back);
    for (int k = 0; k < 6; ++k) ASSERT_EQ(back[k], c[k]);
  }
}

// Neighbouring cells get neighbouring colours; the axes drive red, green and blue.
TEST(HeatmapColours, CellColourFollowsPosition) {
  const glm::uvec3 cells(16, 8, 4);
  EXPECT_LT(cellColour({0, 3, 2}, cells).r, cellColour({15, 3, 2}, cells).r);
  EXPECT_LT(cellColour({5, 0, 2}, cells).g, cellColour({5, 7, 2}, cells).g);
  EXPECT_LT(cellColour({5, 3, 0}, cells).b, cellColour({5, 3, 3}, cells).b);
  EXPECT_EQ(cellColour({5, 3, 1}, cells).r, cellColour({5, 6, 3}, cells).r);
  const float step = cellColour({1, 0, 0}, cells).r - cellColour({0, 0, 0}, cells).r;
  EXPECT_NEAR(step, 0.8f / 16, 1e-6f);
  EXPECT_EQ(cellColour({99, 99, 99}, cells), cellColour({15, 7, 3}, cells)) << "outside cells clamp";
  // Stretched over the cells in view: [5, 9] on x spans the colour range as [0, 4] of 5 cells would.
  EXPECT_EQ(stretchedCellColour({5, 2, 7}, {5, 2, 7}, {9, 2, 7}), cellColour({0, 0, 0}, {5, 1, 1}));
  EXPECT_EQ(stretchedCellColour({9, 2, 7}, {5, 2, 7}, {9, 2, 7}), cellColour({4, 0, 0}, {5, 1, 1}));
}

TEST(HeatmapColours, LinearAndLogScales) {
  EXPECT_FLOAT_EQ(heatmapT(5, 0, 10, false), 0.5f);
  EXPECT_FLOAT_EQ(heatmapT(-3, 0, 10, false), 0.0f);
  EXPECT_FLOAT_EQ(heatmapT(30, 0, 10, false), 1.0f);
  EXPECT_FLOAT_EQ(heatmapT(4, 4, 4, false), 0.5f) << "an empty range is the ramp's middle";
  // Decades equally spaced: 1 .. 1000 puts 10 at a third and 100 at two thirds.
  EXPECT_NEAR(heatmapT(10, 1, 1000, true), 1.0f / 3, 1e-6f);
  EXPECT_NEAR(heatmapT(100, 1, 1000, true), 2.0f / 3, 1e-6f);
  EXPECT_FLOAT_EQ(heatmapT(1000, 1, 1000, true), 1.0f);
  // A range from 0 spans six decades below its top; 0 itself is the bottom.
  EXPECT_FLOAT_EQ(heatmapT(0, 0, 50, true), 0.0f);
  EXPECT_NEAR(heatmapT(50e-3f, 0, 50, true), 0.5f, 1e-5f);
  EXPECT_FLOAT_EQ(heatmapT(3, 0, 0, true), 0.5f);
}

TEST(HeatmapColours, SentinelsAndRampEndsDiffer) {
  const uint32_t noPath = packColour(noPathColour()), noValue = packColour(noValueColour());
  EXPECT_EQ(noPath, 0xFF1F1F1Fu);
  EXPECT_NE(noPath, noValue);
  for (int i = 0; i <= 64; ++i) {
    const uint32_t c = packColour(heatmapRamp(i / 64.0f));
    EXPECT_NE(c, noPath);
    EXPECT_NE(c, noValue);
  }
  HeatmapColouring c;
  c.view = HeatmapView::CacheMean;
  EXPECT_EQ(heatmapPixelColour(c, RL_HEAT_EMPTY), noPath);
  EXPECT_EQ(heatmapPixelColour(c, RL_HEAT_NO_VALUE), noValue);
}

// The legend strip: the heatmap's pixels untouched, the bar's colours the ramp's, labels drawn in text colour.
TEST(HeatmapLegendImage, StripHasBarLabelsAndSwatches) {
  const uint32_t w = 200, h = 50;
  std::vector<uint32_t> image(size_t(w) * h, 0xFF336699u);
  HeatmapStats s;
  s.view = "traversal-steps";
  s.unit = "traversal steps";
  s.scale = "log";
  s.min = 3, s.max = 120;
  s.pixels = w * h, s.pixelsWithValue = w * h - 100, s.pixelsWithoutPath = 100;
  const LegendImage out = withHeatmapLegend(image, w, h, s);
  const LegendLayout l = LegendLayout::forWidth(w);
  ASSERT_EQ(out.width, w);
  ASSERT_EQ(out.height, h + l.height);
  for (size_t i = 0; i < image.size(); ++i) ASSERT_EQ(out.rgba[i], image[i]);
  auto at = [&](uint32_t x, uint32_t y) { return out.rgba[size_t(h + y) * w + x]; };
  const uint32_t span = l.barRight - l.barLeft - 1;
  for (uint32_t x : {l.barLeft, l.barLeft + span / 3, l.barLeft + span / 2, l.barRight - 1})
    EXPECT_EQ(at(x, (l.barTop + l.barBottom) / 2), packColour(heatmapRamp(float(x - l.barLeft) / float(span)))) << x;
  int text = 0, noPath = 0;
  for (uint32_t y = l.barBottom; y < l.height; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      text += at(x, y) == 0xFFE6E6E6u;
      noPath += at(x, y) == packColour(noPathColour());
    }
  EXPECT_GT(text, 100) << "min, max, unit and swatch labels";
  EXPECT_GT(noPath, 20) << "the no-path swatch";
  // No heatmap: the image as it was.
  EXPECT_EQ(withHeatmapLegend(image, w, h, HeatmapStats{}).height, h);
  EXPECT_NE(heatmapLegendLine(s).find("3 .. 120 traversal steps (log"), std::string::npos) << heatmapLegendLine(s);
}

// --heatmap-range and its JSON are validated with the same ranges and words.
TEST(HeatmapSettings, RangeFlagsAndJsonAgree) {
  auto cliError = [](const std::vector<std::string>& args) -> std::string {
    try {
      parseCommonOptions(args);
    } catch (const UsageError& e) {
      return e.what();
    }
    return "";
  };
  auto jsonError = [](const nlohmann::json& range) -> std::string {
    nlohmann::json j = toJson(Settings{});
    j["heatmap_range"] = range;
    try {
      settingsFromJson(j);
    } catch (const SettingsError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_EQ(cliError({"--heatmap-range", "5:2"}), "--heatmap-range min (5) must be below max (2)");
  EXPECT_EQ(jsonError({{"locked", true}, {"min", 5}, {"max", 2}}), "--heatmap-range min (5) must be below max (2)");
  EXPECT_EQ(cliError({"--heatmap-range", "-1:2"}), "--heatmap-range min must be between 0 and 1e+30, got -1");
  EXPECT_EQ(jsonError({{"locked", true}, {"min", -1}, {"max", 2}}), cliError({"--heatmap-range", "-1:2"}));
  EXPECT_NE(cliError({"--heatmap-range", "7"}).find("expects auto or MIN:MAX"), std::string::npos);
  EXPECT_NE(cliError({"--heatmap-key-colour", "rainbow"}).find("cell|rank|hash"), std::string::npos);
  EXPECT_NE(cliError({"--heatmap-scale", "sqrt"}).find("linear|log"), std::string::npos);
  CommonOptions o = parseCommonOptions({"--heatmap-range", "2:40", "--heatmap-scale", "log", "--heatmap-key-colour", "rank"});
  EXPECT_EQ(o.settings.heatmapRange, (HeatmapRange{true, 2.0f, 40.0f}));
  // The sidecar round trip keeps every heatmap field.
  EXPECT_EQ(settingsFromJson(toJson(o.settings)), o.settings);
}

}  // namespace raylab
