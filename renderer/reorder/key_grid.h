// The grid that turns points into sort keys: the scene's bounds, or those bounds clamped to the camera
// position +- a distance (the study's camera-clamped grid), split into cells per axis (near-cubic cells
// by default), and the Morton code of a point's cell as its key. Built on the host; the shaders receive
// it as gpu::GpuKeyGrid.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "renderer/settings/settings.h"
#include "scenes/scene.h"
#include "shaders/key_types.h"

namespace raylab {

struct KeyGrid {
  gpu::GpuKeyGrid gpu{};      // bounds minimum, inverse cell size, cells and bits as the shaders see them
  Bounds bounds;              // the grid's box: finite, every axis of positive extent
  Bounds sceneBounds;         // the scene's box (finite; a unit box around the camera for an empty scene)
  float sceneDiagonal = 0.0f; // of sceneBounds: normalizes prediction errors, bounds learned lengths
  float largestExtent = 0.0f; // of sceneBounds: the fixed length is fixedFactor times this
  bool clamped = false;       // the camera clamp shrank at least one axis
  glm::bvec3 degenerate{false};  // axes of (near) zero extent, widened to a tiny positive size

  glm::uvec3 cells() const { return gpu.cells; }
  glm::uvec3 bits() const { return gpu.bits; }
  uint32_t gridBits() const { return gpu.gridBits; }
  uint64_t cellCount() const { return uint64_t(gpu.cells.x) * gpu.cells.y * gpu.cells.z; }
  // Cell of a point: clamped into the grid; NaN coordinates go to cell 0.
  glm::uvec3 cell(glm::vec3 p) const;
  // Morton code of a cell (bits of unequal axes interleaved while an axis has bits left, lowest first).
  uint32_t morton(glm::uvec3 cell) const;
  // Same box and cells (what a cached length learned on one grid needs to stay valid on the other).
  bool sameCells(const KeyGrid& other) const;
};

// Bits needed to number `cells` cells: ceil(log2(cells)), 0 for one cell.
uint32_t bitsForCells(uint32_t cells);

// Builds the grid for a scene's bounds, the camera position and the grid/clamp settings. Never fails:
// an empty or non-finite scene box becomes a unit box around the camera; a clamp box that misses the scene
// on an axis (camera outside the scene) keeps the scene's extent on that axis, since one slab would carry
// no information; axes of zero extent (a flat scene, clamp distance 0) are widened to a tiny size and get
// one cell when the resolution is automatic.
KeyGrid makeKeyGrid(const Bounds& sceneBounds, glm::vec3 cameraPos, const Settings& settings);

}  // namespace raylab
