#include "renderer/heatmap/heatmap_colours.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include "renderer/reorder/key_functions.h"

namespace raylab {

glm::vec3 heatmapRamp(float t) {
  const float x = std::clamp(t, 0.0f, 1.0f);
  const glm::vec4 v4(1.0f, x, x * x, x * x * x);
  const glm::vec2 v2 = glm::vec2(v4.z, v4.w) * v4.z;
  const glm::vec4 r4(0.13572138f, 4.61539260f, -42.66032258f, 132.13108234f);
  const glm::vec4 g4(0.09140261f, 2.19418839f, 4.84296658f, -14.18503333f);
  const glm::vec4 b4(0.10667330f, 12.64194608f, -60.58204836f, 110.36276771f);
  const glm::vec2 r2(-152.94239396f, 59.28637943f), g2(4.27729857f, 2.82956604f), b2(-89.90310912f, 27.34824973f);
  return glm::clamp(glm::vec3(glm::dot(v4, r4) + glm::dot(v2, r2), glm::dot(v4, g4) + glm::dot(v2, g2),
                              glm::dot(v4, b4) + glm::dot(v2, b2)),
                    0.0f, 1.0f);
}

float heatmapT(float v, float lo, float hi, bool logScale) {
  if (logScale) {
    const float l0 = std::max(lo, hi * 1e-6f);
    if (!(hi > l0) || !(l0 > 0.0f)) return 0.5f;
    return std::clamp(std::log(std::max(v, l0) / l0) / std::log(hi / l0), 0.0f, 1.0f);
  }
  return hi > lo ? std::clamp((v - lo) / (hi - lo), 0.0f, 1.0f) : 0.5f;
}

void deinterleaveBits(uint32_t key, const uint32_t w[6], uint32_t n, uint32_t maxBits, uint32_t c[6]) {
  uint32_t total = 0;
  for (uint32_t k = 0; k < n; ++k) total += w[k];
  const uint32_t drop = total > maxBits ? total - maxBits : 0;
  std::fill(c, c + 6, 0u);
  uint32_t pos = 0;
  for (uint32_t level = 0; level < 32; ++level) {
    bool any = false;
    for (uint32_t k = 0; k < n; ++k) {
      if (level >= w[k]) continue;
      any = true;
      if (pos >= drop) c[k] |= ((key >> (pos - drop)) & 1u) << level;
      ++pos;
    }
    if (!any) break;
  }
}

glm::uvec3 keyCell(KeyStrategy strategy, const gpu::GpuKeyGrid& g, uint32_t key, glm::uvec3& cells) {
  uint32_t c[6];
  cells = g.cells;
  switch (strategy) {
    case KeyStrategy::Direction: {
      const uint32_t bitsU = (g.gridBits + 1) / 2, bitsV = g.gridBits / 2;
      const uint32_t w[6] = {bitsU, bitsV, 0, 0, 0, 0};
      deinterleaveBits(key, w, 2, 32, c);
      cells = glm::uvec3(1u << bitsU, 1u << bitsV, 1u);
      return {c[0], c[1], 0};
    }
    case KeyStrategy::OriginDirection: {
      const uint32_t m = g.maxAxisBits;
      const uint32_t w[6] = {g.bits.x, g.bits.y, g.bits.z, m, m, 0};
      deinterleaveBits(key, w, 5, RL_KEY_MAX_SPATIAL_BITS, c);
      return {c[0], c[1], c[2]};
    }
    case KeyStrategy::TwoPoint: {
      const uint32_t w[6] = {g.bits.x, g.bits.y, g.bits.z, g.bits.x, g.bits.y, g.bits.z};
      deinterleaveBits(key, w, 6, RL_KEY_TWO_POINT_BITS, c);
      return {c[3], c[4], c[5]};
    }
    case KeyStrategy::DeadLast:
    case KeyStrategy::None: cells = glm::uvec3(1); return glm::uvec3(0);
    default: {
      const uint32_t w[6] = {g.bits.x, g.bits.y, g.bits.z, 0, 0, 0};
      deinterleaveBits(key, w, 3, 32, c);
      return {c[0], c[1], c[2]};
    }
  }
}

glm::vec3 cellColour(glm::uvec3 cell, glm::uvec3 cells) {
  const glm::vec3 f = (glm::vec3(glm::min(cell, cells - 1u)) + 0.5f) / glm::vec3(glm::max(cells, glm::uvec3(1)));
  return 0.15f + 0.8f * f;
}

glm::vec3 stretchedCellColour(glm::uvec3 cell, glm::uvec3 lo, glm::uvec3 hi) {
  const glm::uvec3 l = glm::min(lo, cell), h = glm::max(hi, cell);
  return cellColour(cell - l, h - l + 1u);
}

glm::vec3 hashColour(uint32_t key) {
  const uint32_t h = pcgHash(key);
  return 0.25f + 0.75f * glm::vec3(float(h & 255u), float((h >> 8) & 255u), float((h >> 16) & 255u)) / 255.0f;
}

glm::vec3 noPathColour() { return glm::vec3(0.12f); }
glm::vec3 noValueColour() { return glm::vec3(0.85f); }
glm::vec3 cellHitColour(bool hit) { return hit ? glm::vec3(0.2f, 0.8f, 0.3f) : glm::vec3(0.85f, 0.2f, 0.2f); }

uint32_t packColour(glm::vec3 c) {
  const glm::uvec3 b = glm::uvec3(glm::clamp(c, 0.0f, 1.0f) * 255.0f + 0.5f);
  return b.r | (b.g << 8) | (b.b << 16) | (255u << 24);
}

uint32_t heatmapPixelColour(const HeatmapColouring& c, uint32_t heat) {
  if (heat == RL_HEAT_EMPTY) return packColour(noPathColour());
  if (heat == RL_HEAT_NO_VALUE) return packColour(noValueColour());
  if (c.view == HeatmapView::SortKey && c.keyColour == HeatmapKeyColour::Hash) return packColour(hashColour(heat));
  if (c.view == HeatmapView::SortKey && c.keyColour == HeatmapKeyColour::Cell) {
    glm::uvec3 cells(1);
    const glm::uvec3 cell = c.hasGrid ? keyCell(c.strategy, c.grid, heat, cells) : glm::uvec3(0);
    return packColour(stretchedCellColour(cell, c.cellLo, c.cellHi));
  }
  if (c.view == HeatmapView::CellHit) return packColour(cellHitColour(std::bit_cast<float>(heat) > 0.5f));
  return packColour(heatmapRamp(heatmapT(std::bit_cast<float>(heat), c.lo, c.hi, c.logScale)));
}

}  // namespace raylab
