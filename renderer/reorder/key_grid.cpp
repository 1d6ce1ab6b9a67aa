#include "renderer/reorder/key_grid.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include "renderer/reorder/key_functions.h"

namespace raylab {
namespace {

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The scene's box, or a unit box around the camera (or the origin) when the scene gives none.
Bounds usableSceneBounds(const Bounds& scene, glm::vec3 camera) {
  if (!scene.empty() && finite(scene.min) && finite(scene.max)) return scene;
  glm::vec3 c = finite(camera) ? camera : glm::vec3(0.0f);
  Bounds b;
  b.min = c - glm::vec3(1.0f);
  b.max = c + glm::vec3(1.0f);
  return b;
}

uint32_t clampCells(uint32_t n) { return std::clamp<uint32_t>(n, 1u, SettingLimits::kMaxGridCellsPerAxis); }

}  // namespace

uint32_t bitsForCells(uint32_t cells) { return cells <= 1u ? 0u : 32u - std::countl_zero(cells - 1u); }

glm::uvec3 KeyGrid::cell(glm::vec3 p) const { return cellOf(gpu, p); }

uint32_t KeyGrid::morton(glm::uvec3 c) const { return mortonCell(gpu, c); }

bool KeyGrid::sameCells(const KeyGrid& o) const {
  return gpu.boundsMin == o.gpu.boundsMin && gpu.invCellSize == o.gpu.invCellSize && gpu.cells == o.gpu.cells;
}

KeyGrid makeKeyGrid(const Bounds& sceneBoundsIn, glm::vec3 camera, const Settings& s) {
  KeyGrid g;
  g.sceneBounds = usableSceneBounds(sceneBoundsIn, camera);
  glm::vec3 sceneExtent = g.sceneBounds.max - g.sceneBounds.min;
  g.sceneDiagonal = glm::length(sceneExtent);
  g.largestExtent = std::max({sceneExtent.x, sceneExtent.y, sceneExtent.z});

  Bounds b = g.sceneBounds;
  float distance = s.clampDistance;
  if (s.clampToCamera && finite(camera) && distance >= 0.0f) {  // NaN distance: no clamp
    distance = std::min(distance, SettingLimits::kMaxClampDistance);
    for (int a = 0; a < 3; ++a) {
      float lo = std::max(g.sceneBounds.min[a], camera[a] - distance);
      float hi = std::min(g.sceneBounds.max[a], camera[a] + distance);
      if (lo > hi) continue;  // the clamp box misses the scene on this axis: keep the scene's extent
      g.clamped = g.clamped || lo > b.min[a] || hi < b.max[a];
      b.min[a] = lo;
      b.max[a] = hi;
    }
  }

  // A tiny positive size for degenerate axes: large enough that min + size != min in float at this
  // magnitude (1e-5 relative is about 80 ulps), small enough not to matter for any real scene.
  float scale = std::max({1.0f, std::abs(b.min.x), std::abs(b.min.y), std::abs(b.min.z), std::abs(b.max.x),
                          std::abs(b.max.y), std::abs(b.max.z)});
  float eps = scale * 1e-5f;
  for (int a = 0; a < 3; ++a) {
    if (b.max[a] - b.min[a] >= eps) continue;
    float c = 0.5f * (b.min[a] + b.max[a]);
    b.min[a] = c - eps;
    b.max[a] = c + eps;
    g.degenerate[a] = true;
  }
  g.bounds = b;
  glm::vec3 extent = b.max - b.min;

  glm::uvec3 cells;
  if (s.grid.automatic) {
    // Near-cubic cells: autoCells along the largest real axis, the others in proportion.
    float largest = 0.0f;
    for (int a = 0; a < 3; ++a)
      if (!g.degenerate[a]) largest = std::max(largest, extent[a]);
    uint32_t n = clampCells(s.grid.autoCells);
    for (int a = 0; a < 3; ++a)
      cells[a] = g.degenerate[a] || largest <= 0.0f
                     ? 1u
                     : clampCells(static_cast<uint32_t>(std::lround(n * double(extent[a]) / largest)));
  } else {
    cells = glm::uvec3(clampCells(s.grid.cells.x), clampCells(s.grid.cells.y), clampCells(s.grid.cells.z));
  }

  gpu::GpuKeyGrid& k = g.gpu;
  k.boundsMin = b.min;
  k.cells = cells;
  k.invCellSize = glm::vec3(cells) / extent;
  k.bits = glm::uvec3(bitsForCells(cells.x), bitsForCells(cells.y), bitsForCells(cells.z));
  k.gridBits = k.bits.x + k.bits.y + k.bits.z;
  k.maxAxisBits = std::max({k.bits.x, k.bits.y, k.bits.z});
  k.spatialBits = k.gridBits;
  k.cacheShift = 0;
  k.cacheCells = cells;
  return g;
}

}  // namespace raylab
