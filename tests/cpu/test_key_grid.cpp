// The key grid on the host: resolution, bits, Morton order, and the boxes where methods fail (flat
// scenes, camera outside the scene, clamp distance 0 or huge, empty scenes) giving finite, valid grids.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "renderer/reorder/key_functions.h"
#include "renderer/reorder/key_grid.h"

namespace raylab {
namespace {

Bounds box(glm::vec3 lo, glm::vec3 hi) {
  Bounds b;
  b.min = lo;
  b.max = hi;
  return b;
}

Settings explicitCells(glm::uvec3 cells) {
  Settings s;
  s.grid.automatic = false;
  s.grid.cells = cells;
  return s;
}

// Everything a grid must satisfy whatever its inputs.
void expectValid(const KeyGrid& g) {
  for (int a = 0; a < 3; ++a) {
    EXPECT_TRUE(std::isfinite(g.bounds.min[a]) && std::isfinite(g.bounds.max[a]));
    EXPECT_LT(g.bounds.min[a], g.bounds.max[a]);
    EXPECT_TRUE(std::isfinite(g.gpu.invCellSize[a]) && g.gpu.invCellSize[a] > 0.0f);
    EXPECT_GE(g.gpu.cells[a], 1u);
    EXPECT_LE(g.gpu.cells[a], SettingLimits::kMaxGridCellsPerAxis);
    EXPECT_EQ(g.gpu.bits[a], bitsForCells(g.gpu.cells[a]));
  }
  EXPECT_TRUE(std::isfinite(g.sceneDiagonal));
  EXPECT_LE(g.gridBits(), 30u);
}

TEST(KeyGrid, AutoResolutionGivesNearCubicCells) {
  Settings s;
  s.grid.autoCells = 64;
  KeyGrid g = makeKeyGrid(box({0, 0, 0}, {150, 50, 150}), {75, 25, 75}, s);
  expectValid(g);
  EXPECT_EQ(g.cells(), glm::uvec3(64, 21, 64));
  EXPECT_EQ(g.bits(), glm::uvec3(6, 5, 6));
  EXPECT_EQ(g.gridBits(), 17u);
  EXPECT_FALSE(g.clamped);
}

TEST(KeyGrid, ExplicitResolutionAndBits) {
  KeyGrid g = makeKeyGrid(box({0, 0, 0}, {1, 1, 1}), {0, 0, 0}, explicitCells({7, 3, 100}));
  EXPECT_EQ(g.bits(), glm::uvec3(3, 2, 7));
  EXPECT_EQ(g.gridBits(), 12u);
  EXPECT_EQ(makeKeyGrid(box({0, 0, 0}, {1, 1, 1}), {}, explicitCells({1, 1, 1})).gridBits(), 0u);
  EXPECT_EQ(makeKeyGrid(box({0, 0, 0}, {1, 1, 1}), {}, explicitCells({1024, 1024, 1024})).gridBits(), 30u);
  // Out-of-range requests are clamped to the limits, never rejected.
  KeyGrid big = makeKeyGrid(box({0, 0, 0}, {1, 1, 1}), {}, explicitCells({0, 5000, 2}));
  EXPECT_EQ(big.cells(), glm::uvec3(1, 1024, 2));
  EXPECT_EQ(bitsForCells(1), 0u);
  EXPECT_EQ(bitsForCells(2), 1u);
  EXPECT_EQ(bitsForCells(3), 2u);
  EXPECT_EQ(bitsForCells(1024), 10u);
  EXPECT_EQ(bitsForCells(1025), 11u);
}

TEST(KeyGrid, CellsClampPointsAndMapNanToZero) {
  KeyGrid g = makeKeyGrid(box({0, 0, 0}, {10, 10, 10}), {}, explicitCells({10, 5, 2}));
  EXPECT_EQ(g.cell({0.5f, 0.5f, 0.5f}), glm::uvec3(0, 0, 0));
  EXPECT_EQ(g.cell({9.99f, 9.99f, 9.99f}), glm::uvec3(9, 4, 1));
  EXPECT_EQ(g.cell({10, 10, 10}), glm::uvec3(9, 4, 1));  // the max corner belongs to the last cell
  EXPECT_EQ(g.cell({-5, 50, 3}), glm::uvec3(0, 4, 0));
  float inf = std::numeric_limits<float>::infinity();
  float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(g.cell({nan, inf, -inf}), glm::uvec3(0, 4, 0));
  EXPECT_EQ(g.cell({3.5f, 2.5f, 7.0f}), glm::uvec3(3, 1, 1));
}

TEST(KeyGrid, MortonInterleavesWhileAxesHaveBits) {
  KeyGrid cube = makeKeyGrid(box({0, 0, 0}, {1, 1, 1}), {}, explicitCells({4, 4, 4}));
  EXPECT_EQ(cube.morton({1, 0, 0}), 1u);
  EXPECT_EQ(cube.morton({0, 1, 0}), 2u);
  EXPECT_EQ(cube.morton({0, 0, 1}), 4u);
  EXPECT_EQ(cube.morton({1, 1, 1}), 7u);
  EXPECT_EQ(cube.morton({2, 0, 0}), 8u);
  EXPECT_EQ(cube.morton({3, 3, 3}), 63u);
  // x has 2 bits, y 1, z 0: bit order (low to high) x0 y0 x1.
  KeyGrid flat = makeKeyGrid(box({0, 0, 0}, {1, 1, 1}), {}, explicitCells({4, 2, 1}));
  EXPECT_EQ(flat.morton({3, 1, 0}), 7u);
  EXPECT_EQ(flat.morton({2, 0, 0}), 4u);
  EXPECT_EQ(flat.morton({1, 1, 0}), 3u);
  EXPECT_EQ(flat.morton({0, 1, 0}), 2u);
}

TEST(KeyGrid, InterleaveDropsTheFinestLevelsBeyondMaxBits) {
  const uint32_t c[6] = {0x3FF, 0, 0x3FF, 0, 0x3FF, 0};
  const uint32_t w[6] = {10, 10, 10, 10, 10, 10};  // 60 bits
  uint32_t key = interleaveBits(c, w, 6, 31);
  EXPECT_LT(key, 1u << 31);
  // Levels are 6 bits (c0..c5); 60 - 31 = 29 low bits dropped, so bit 0 of the key is bit 29 of the full
  // code, i.e. component 5 (0) of level 4; the top level (bits 54..59) holds 1,0,1,0,1,0 -> key bits 25..30.
  EXPECT_EQ((key >> 25) & 0x3F, 0b010101u);
  EXPECT_EQ(key & 1u, 0u);
}

TEST(KeyGrid, ClampToCameraShrinksTheBox) {
  Settings s;
  s.clampToCamera = true;
  s.clampDistance = 10;
  KeyGrid g = makeKeyGrid(box({0, 0, 0}, {100, 20, 100}), {50, 5, 95}, s);
  expectValid(g);
  EXPECT_TRUE(g.clamped);
  EXPECT_EQ(g.bounds.min, glm::vec3(40, 0, 85));
  EXPECT_EQ(g.bounds.max, glm::vec3(60, 15, 100));
  EXPECT_FLOAT_EQ(g.largestExtent, 100.0f);  // the fixed length still follows the scene, not the clamp box
}

TEST(KeyGrid, CameraOutsideTheSceneKeepsTheSceneExtentOnMissedAxes) {
  Settings s;
  s.clampToCamera = true;
  s.clampDistance = 5;
  KeyGrid g = makeKeyGrid(box({0, 0, 0}, {10, 10, 10}), {100, 3, -50}, s);
  expectValid(g);
  EXPECT_EQ(g.bounds.min.x, 0.0f);  // x: clamp box [95, 105] misses [0, 10]
  EXPECT_EQ(g.bounds.max.x, 10.0f);
  EXPECT_EQ(g.bounds.min.y, 0.0f);  // y: [-2, 8] overlaps
  EXPECT_EQ(g.bounds.max.y, 8.0f);
  EXPECT_EQ(g.bounds.min.z, 0.0f);  // z: [-55, -45] misses
  EXPECT_EQ(g.bounds.max.z, 10.0f);
}

TEST(KeyGrid, DegenerateBoxesStayFiniteAndValid) {
  Settings s;
  // A flat scene: zero extent on y gets one cell and a tiny positive size.
  KeyGrid flat = makeKeyGrid(box({0, 2, 0}, {10, 2, 10}), {5, 3, 5}, s);
  expectValid(flat);
  EXPECT_TRUE(flat.degenerate.y);
  EXPECT_EQ(flat.cells(), glm::uvec3(64, 1, 64));
  // Clamp distance 0: a point-sized box, one cell.
  s.clampToCamera = true;
  s.clampDistance = 0;
  KeyGrid zero = makeKeyGrid(box({0, 0, 0}, {10, 10, 10}), {5, 5, 5}, s);
  expectValid(zero);
  EXPECT_EQ(zero.cells(), glm::uvec3(1, 1, 1));
  // Huge clamp: the scene's own box.
  s.clampDistance = 1e6f;
  KeyGrid huge = makeKeyGrid(box({0, 0, 0}, {10, 10, 10}), {5, 5, 5}, s);
  expectValid(huge);
  EXPECT_EQ(huge.bounds.max, glm::vec3(10));
  EXPECT_FALSE(huge.clamped);
  // Empty scene, NaN camera, explicit cells on a flat box, far-away coordinates.
  expectValid(makeKeyGrid(Bounds{}, {1, 2, 3}, Settings{}));
  float nan = std::numeric_limits<float>::quiet_NaN();
  expectValid(makeKeyGrid(box({0, 0, 0}, {1, 1, 1}), {nan, 0, 0}, s));
  expectValid(makeKeyGrid(box({0, 0, 0}, {10, 0, 10}), {}, explicitCells({1024, 1024, 1024})));
  expectValid(makeKeyGrid(box({1e7f, 1e7f, 1e7f}, {1e7f, 1e7f, 1e7f}), {}, Settings{}));
}

}  // namespace
}  // namespace raylab
