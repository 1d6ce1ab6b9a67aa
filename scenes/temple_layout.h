// Where the temple's hall stands (at TempleParams::size 1), shared by the temple and by the detail that
// temple-detail adds inside the hall, so that the added geometry follows the hall when its layout changes.
#pragma once

#include <algorithm>

namespace raylab::temple_layout {

// The hall's inner walls (the walls themselves are 2 units thick, outside these bounds).
constexpr float kHallInnerWest = -34.0f, kHallInnerEast = 34.0f;
constexpr float kHallInnerSouth = -68.0f, kHallInnerNorth = -26.0f;
constexpr float kHallWallTop = 18.0f;
// The dais at the south end (x in [-kDaisHalfWidth, kDaisHalfWidth], top at kDaisTop).
constexpr float kDaisHalfWidth = 10.0f, kDaisTop = 1.0f;

// Two rows of columns at x = -kHallColumnX and +kHallColumnX: plinth to y = kPlinthTop, round shaft of
// kHallShaftRadius up to the capital, which starts kCapitalDepth below the column's top.
constexpr float kHallColumnX = 11.0f;
constexpr float kHallColumnHeight = 16.3f;
constexpr float kHallShaftRadius = 0.9f;
constexpr float kPlinthTop = 0.6f;
constexpr float kCapitalDepth = 0.75f;

// z of column i of `columns` in each row, from the north end of the nave to the south.
inline float hallColumnZ(int i, int columns) {
  return -30.0f - 30.0f * static_cast<float>(i) / static_cast<float>(std::max(columns - 1, 1));
}

}  // namespace raylab::temple_layout
