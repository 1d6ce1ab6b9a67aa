// The length cache of the adaptive strategies (average, ema, gaussian): per (cache cell, direction octant)
// the lengths the rays starting there actually travelled. Sized by what the scene occupies, not by the
// grid's volume: the host finds the cells the triangles touch, numbers them compactly and builds an
// open-addressing hash table from cell index to that number; lookups of other cells fall back to the fixed
// length. When the scene occupies more than a budget of cells, cache cells become 2x2x2, 4x4x4, ... key
// cells until it fits. The statistics themselves live only on the GPU (key_learn.comp, key_merge.comp).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>
#include <vulkan/vulkan.h>

#include "renderer/vk/gpu_buffer.h"
#include "renderer/reorder/key_grid.h"
#include "scenes/scene.h"
#include "shaders/key_types.h"

namespace raylab {

class VulkanContext;

// Occupied cache cells beyond which the cache coarsens (2^17 cells x 8 octants x 40 bytes = 42 MB at most).
constexpr uint32_t kMaxCacheCells = 1u << 17;
// A triangle is sampled on a barycentric lattice of at most this many steps per edge (spacing half a cache
// cell, so thin slivers of a cell may be missed; such cells just fall back to the fixed length).
constexpr uint32_t kMaxTriangleSteps = 1024;

struct LengthCacheLayout {
  uint32_t cacheShift = 0;        // cache cell = key cell >> cacheShift
  glm::uvec3 cacheCells{1u};      // cache cells per axis
  uint32_t occupiedCells = 0;     // compact ids 0 .. occupiedCells - 1, in increasing cell index
  std::vector<uint32_t> slotKeys;    // cell index + 1, 0 empty; size a power of two, at least 2x occupied
  std::vector<uint32_t> slotValues;  // compact id
};

// Finds the cache cells the triangles (and the camera) occupy and builds the hash table over them.
LengthCacheLayout buildLengthCacheLayout(const KeyGrid& grid, std::span<const Triangle> triangles,
                                         glm::vec3 camera, uint32_t maxCells = kMaxCacheCells);

// Fixed-point step of learned lengths for lengths in [0, lengthMax] and batches of up to maxPaths samples:
// 2^-P of lengthMax with P = min(22, (62 - ceil(log2 maxPaths)) / 2), so a batch's 64-bit sum of squares
// (|q| <= 2^P, up to 2^ceil(log2 maxPaths) samples) cannot overflow. 512x256 paths: P = 22.
float lengthCacheUnit(float lengthMax, uint32_t maxPaths);

class LengthCache {
 public:
  struct Contents {
    std::vector<uint32_t> slotKeys;
    std::vector<uint32_t> slotValues;
    std::vector<gpu::GpuCacheEntry> entries;
  };

  LengthCache(const VulkanContext& ctx, LengthCacheLayout layout);

  const LengthCacheLayout& layout() const { return layout_; }
  uint32_t entryCount() const { return layout_.occupiedCells * RL_OCTANTS; }
  // Buffer addresses and table shape; the caller adds the length range and the strategy's parameters.
  gpu::GpuLengthCache gpuView() const;
  // Forgets every sample (submits and waits).
  void clear();
  // Records the reset of the per-bounce touched-entry counter (before key_learn.comp).
  void recordResetTouched(VkCommandBuffer cmd) const;

  uint64_t memoryBytes() const;
  // Fraction of entries holding samples (downloads the entries).
  double occupancy() const;
  // Samples the Gaussian strategy rejected as outliers since the last clear.
  uint32_t outliersRejected() const;
  Contents download() const;

 private:
  const VulkanContext* ctx_;
  LengthCacheLayout layout_;
  GpuBuffer slotKeys_;
  GpuBuffer slotValues_;
  GpuBuffer entries_;
  GpuBuffer batches_;
  GpuBuffer touched_;
};

}  // namespace raylab
