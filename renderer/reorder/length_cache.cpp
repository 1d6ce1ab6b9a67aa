#include "renderer/reorder/length_cache.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <unordered_set>

#include "renderer/reorder/key_functions.h"
#include "renderer/vk/vk_context.h"

namespace raylab {
namespace {

// Adds the cache cells touched by one triangle; false once more than maxCells are occupied.
bool addTriangle(const gpu::GpuKeyGrid& g, const Triangle& tri, std::unordered_set<uint32_t>& cells,
                 uint32_t maxCells) {
  glm::vec3 e1 = tri.v[1] - tri.v[0];
  glm::vec3 e2 = tri.v[2] - tri.v[0];
  glm::vec3 e3 = tri.v[2] - tri.v[1];
  // Steps so that neighbouring lattice points are at most half a cache cell apart on every axis.
  glm::vec3 perCell = g.invCellSize / float(1u << g.cacheShift);
  glm::vec3 span = glm::max(glm::abs(e1), glm::max(glm::abs(e2), glm::abs(e3))) * perCell * 2.0f;
  float want = std::ceil(std::max({span.x, span.y, span.z, 1.0f}));
  uint32_t n = want < float(kMaxTriangleSteps) ? static_cast<uint32_t>(want) : kMaxTriangleSteps;
  for (uint32_t i = 0; i <= n; ++i)
    for (uint32_t j = 0; i + j <= n; ++j) {
      glm::vec3 p = tri.v[0] + e1 * (float(i) / float(n)) + e2 * (float(j) / float(n));
      cells.insert(cacheCellIndex(g, cellOf(g, p)));
      if (cells.size() > maxCells) return false;
    }
  return true;
}

uint32_t nextPowerOfTwo(uint32_t v) { return v <= 1u ? 1u : 1u << (32u - std::countl_zero(v - 1u)); }

}  // namespace

LengthCacheLayout buildLengthCacheLayout(const KeyGrid& grid, std::span<const Triangle> triangles, glm::vec3 camera,
                                         uint32_t maxCells) {
  maxCells = std::max(maxCells, 1u);
  LengthCacheLayout layout;
  std::unordered_set<uint32_t> cells;
  for (uint32_t shift = 0;; ++shift) {
    gpu::GpuKeyGrid g = grid.gpu;
    g.cacheShift = shift;
    g.cacheCells = ((g.cells - 1u) >> shift) + 1u;
    cells.clear();
    cells.insert(cacheCellIndex(g, cellOf(g, camera)));
    bool fits = true;
    for (const Triangle& tri : triangles)
      if (!(fits = addTriangle(g, tri, cells, maxCells))) break;
    // At shift 10 every axis has one cache cell, which always fits.
    if (fits || shift >= 10) {
      layout.cacheShift = shift;
      layout.cacheCells = g.cacheCells;
      break;
    }
  }

  std::vector<uint32_t> sorted(cells.begin(), cells.end());
  std::sort(sorted.begin(), sorted.end());  // compact ids in cell order: deterministic, memory-coherent
  layout.occupiedCells = static_cast<uint32_t>(sorted.size());
  uint32_t slots = nextPowerOfTwo(std::max<uint32_t>(16u, 2u * layout.occupiedCells));  // load <= 1/2
  layout.slotKeys.assign(slots, 0u);
  layout.slotValues.assign(slots, 0u);
  for (uint32_t id = 0; id < sorted.size(); ++id) {
    uint32_t key = sorted[id] + 1u;
    uint32_t slot = hashCell(key) & (slots - 1u);
    while (layout.slotKeys[slot] != 0u) slot = (slot + 1u) & (slots - 1u);
    layout.slotKeys[slot] = key;
    layout.slotValues[slot] = id;
  }
  return layout;
}

float lengthCacheUnit(float lengthMax, uint32_t maxPaths) {
  uint32_t logN = std::max(1u, bitsForCells(std::max(maxPaths, 2u)));
  uint32_t precision = std::min(22u, (62u - std::min(logN, 32u)) / 2u);
  return lengthMax / float(1u << precision);
}

LengthCache::LengthCache(const VulkanContext& ctx, LengthCacheLayout layout)
    : ctx_(&ctx), layout_(std::move(layout)) {
  slotKeys_ = makeBufferFrom(ctx, layout_.slotKeys);
  slotValues_ = makeBufferFrom(ctx, layout_.slotValues);
  entries_ = GpuBuffer(ctx, uint64_t(entryCount()) * sizeof(gpu::GpuCacheEntry));
  batches_ = GpuBuffer(ctx, uint64_t(entryCount()) * sizeof(gpu::GpuCacheBatch));
  // [0] touched count, [1] outliers, then at most one id per entry (sized by entries, not paths, so a
  // resolution change keeps the cache).
  touched_ = GpuBuffer(ctx, (uint64_t(entryCount()) + 2u) * sizeof(uint32_t));
  clear();
}

gpu::GpuLengthCache LengthCache::gpuView() const {
  gpu::GpuLengthCache c{};
  c.slotKeys = slotKeys_.address();
  c.slotValues = slotValues_.address();
  c.entries = entries_.address();
  c.batches = batches_.address();
  c.touched = touched_.address();
  c.slotMask = static_cast<uint32_t>(layout_.slotKeys.size()) - 1u;
  c.entryCount = entryCount();
  return c;
}

void LengthCache::clear() {
  ctx_->submitAndWait([&](VkCommandBuffer cmd) {
    entries_.recordFill(cmd, 0u);
    batches_.recordFill(cmd, 0u);
    touched_.recordFill(cmd, 0u);
  });
}

void LengthCache::recordResetTouched(VkCommandBuffer cmd) const {
  vkCmdFillBuffer(cmd, touched_.handle(), 0, sizeof(uint32_t), 0u);
}

uint64_t LengthCache::memoryBytes() const {
  return slotKeys_.size() + slotValues_.size() + entries_.size() + batches_.size() + touched_.size();
}

double LengthCache::occupancy() const {
  if (entryCount() == 0) return 0.0;
  auto entries = entries_.downloadVector<gpu::GpuCacheEntry>(entryCount());
  size_t used = std::count_if(entries.begin(), entries.end(), [](const auto& e) { return e.count > 0u; });
  return double(used) / double(entries.size());
}

uint32_t LengthCache::outliersRejected() const {
  uint32_t header[2];
  touched_.download(header, sizeof(header));
  return header[1];
}

LengthCache::Contents LengthCache::download() const {
  return {layout_.slotKeys, layout_.slotValues, entries_.downloadVector<gpu::GpuCacheEntry>(entryCount())};
}

}  // namespace raylab
