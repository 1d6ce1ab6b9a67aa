// The length cache's layout on the host: its size follows the occupied cells, not the grid volume, and
// it coarsens when the scene occupies too many cells.
#include <gtest/gtest.h>

#include "tests/test_key_support.h"

namespace raylab::test {
namespace {

Settings cells1024() {
  Settings s;
  s.grid.automatic = false;
  s.grid.cells = {1024, 1024, 1024};
  return s;
}

TEST(LengthCacheLayout, MemoryFollowsOccupiedCellsNotGridVolume) {
  // Two tiny triangles at opposite corners of a 100^3 box: a 1024^3 grid has 2^30 cells, the scene
  // touches a handful.
  Scene sparse;
  Triangle a, b;
  a.v[0] = {0, 0, 0}, a.v[1] = {0.05f, 0, 0}, a.v[2] = {0, 0.05f, 0};
  b.v[0] = {100, 100, 100}, b.v[1] = {99.95f, 100, 100}, b.v[2] = {100, 99.95f, 100};
  sparse.triangles = {a, b};
  KeyGrid grid = makeKeyGrid(sparse.bounds(), {50, 50, 50}, cells1024());
  LengthCacheLayout layout = buildLengthCacheLayout(grid, sparse.triangles, {50, 50, 50});
  EXPECT_EQ(layout.cacheShift, 0u);
  EXPECT_GE(layout.occupiedCells, 3u);  // two corners and the camera
  EXPECT_LE(layout.occupiedCells, 20u);
  EXPECT_LE(layout.slotKeys.size(), 64u);
  // Every triangle vertex's cell is in the table.
  gpu::GpuLengthCache view{};
  view.slotMask = static_cast<uint32_t>(layout.slotKeys.size()) - 1;
  KeyEnv env;
  env.slotKeys = layout.slotKeys;
  env.slotValues = layout.slotValues;
  for (const Triangle& t : sparse.triangles)
    for (glm::vec3 v : t.v) {
      int32_t e = cacheEntry(view, env, grid.gpu, grid.cell(v), {1, 1, 1});
      EXPECT_GE(e, 0);
      EXPECT_LT(e, int32_t(layout.occupiedCells * RL_OCTANTS));
    }
  EXPECT_EQ(cacheEntry(view, env, grid.gpu, grid.cell({30, 70, 10}), {1, 1, 1}), -1);  // empty space

  // A denser scene occupies more cells at the same grid: memory scales with the surface, not the volume.
  Scene box = boxScene({0, 0, 0}, {100, 100, 100});
  KeyGrid boxGrid = makeKeyGrid(box.bounds(), {50, 50, 50}, cells1024());
  LengthCacheLayout dense = buildLengthCacheLayout(boxGrid, box.triangles, {50, 50, 50});
  EXPECT_GT(dense.occupiedCells, 100u * layout.occupiedCells);
  EXPECT_LE(dense.occupiedCells, kMaxCacheCells);
}

TEST(LengthCacheLayout, CoarsensWhenTheSceneOccupiesTooManyCells) {
  Scene box = boxScene({0, 0, 0}, {10, 10, 10});
  KeyGrid grid = makeKeyGrid(box.bounds(), {5, 5, 5}, cells1024());
  LengthCacheLayout layout = buildLengthCacheLayout(grid, box.triangles, {5, 5, 5}, 5000);
  EXPECT_GT(layout.cacheShift, 0u);
  EXPECT_LE(layout.occupiedCells, 5000u);
  EXPECT_EQ(layout.cacheCells.x, ((1024u - 1u) >> layout.cacheShift) + 1u);
  EXPECT_EQ(lengthCacheUnit(1.0f, 512 * 256), 1.0f / float(1 << 22));  // 2^17 paths: 22 bits
  EXPECT_EQ(lengthCacheUnit(1.0f, 8192 * 8192), 1.0f / float(1 << 18));
}

}  // namespace
}  // namespace raylab::test
