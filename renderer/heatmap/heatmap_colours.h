// Heatmap values to colours on the host: the twins of shaders/heatmap_colours.glsl (same names, same
// order of operations), used by the legend, the legend burned into saved PNGs, the hover readout and the
// tests that check the GPU's colours against them.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "renderer/settings/settings.h"
#include "shaders/heatmap_types.h"

namespace raylab {

// The Turbo ramp (Mikhailov 2019, polynomial fit), t in [0, 1].
glm::vec3 heatmapRamp(float t);
// Where v lies between lo and hi on a linear or log scale, in [0, 1] (log: from max(lo, hi * 1e-6)).
float heatmapT(float v, float lo, float hi, bool logScale);
// The inverse of the key functions' bit interleaving (key_functions.h interleaveBits).
void deinterleaveBits(uint32_t key, const uint32_t w[6], uint32_t n, uint32_t maxBits, uint32_t c[6]);
// The cell a live key of `strategy` encodes, and the cells per axis of its space (heatmap_colours.glsl).
glm::uvec3 keyCell(KeyStrategy strategy, const gpu::GpuKeyGrid& grid, uint32_t key, glm::uvec3& cells);
glm::vec3 cellColour(glm::uvec3 cell, glm::uvec3 cells);
glm::vec3 stretchedCellColour(glm::uvec3 cell, glm::uvec3 lo, glm::uvec3 hi);
glm::vec3 hashColour(uint32_t key);
glm::vec3 noPathColour();
glm::vec3 noValueColour();
glm::vec3 cellHitColour(bool hit);
// RGBA8, R in the low byte, as the display image holds it.
uint32_t packColour(glm::vec3 c);

// How heatmap_colorize.comp colours one pixel's heat word: the whole decision, for the tests' reference.
struct HeatmapColouring {
  HeatmapView view = HeatmapView::None;
  HeatmapKeyColour keyColour = HeatmapKeyColour::Cell;
  KeyStrategy strategy = KeyStrategy::None;
  gpu::GpuKeyGrid grid{};
  bool hasGrid = false;
  bool logScale = false;
  float lo = 0.0f, hi = 1.0f;  // the colour range used
  glm::uvec3 cellLo{0}, cellHi{0};  // sort keys by cell: the cells the frame's keys span
};
uint32_t heatmapPixelColour(const HeatmapColouring& c, uint32_t heat);

}  // namespace raylab
