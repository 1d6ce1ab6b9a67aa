// `clutter:N`: a closed storeroom packed with small, randomly placed and oriented objects (shelves of
// books, tables laid with tableware, chairs upright and tipped over, potted plants of thin leaves, crates
// and boxes in piles, cables hanging from the ceiling), lit by a few small ceiling lights and a window of
// sky. It is the lab's low-coherence case: neighbouring paths after the first bounce go through very
// different amounts of geometry, so the unsorted wavefront's virtual warp efficiency at bounces >= 1 is
// about that of real interiors (at most 0.25), where the temple and Sponza have 0.56-0.58.
//
// N is the triangle count (5e4 to 3e6, "clutter" alone is kClutterDefaultTriangles): the room and its
// shelves are fixed and the loose objects are added, in one fixed random order, until the count is reached,
// so a larger N is a more crowded room. Deterministic: the same N and seed (Settings::clutterSeed, the
// order and places of the objects) give the same triangles.
#pragma once

#include <cstdint>
#include <string>

#include "scenes/scene.h"

namespace raylab {

inline constexpr const char* kClutterName = "clutter";
inline constexpr uint32_t kClutterMinTriangles = 50000;  // the room and its shelves alone have about 22,500
inline constexpr uint32_t kClutterMaxTriangles = 3000000;
inline constexpr uint32_t kClutterDefaultTriangles = 200000;
inline constexpr uint32_t kClutterDefaultSeed = 21;

// True for "clutter" and "clutter:<anything>": names the family claims, good size or not.
bool isClutterName(const std::string& name);
// The triangle count a family name asks for; throws std::invalid_argument with the accepted range.
uint32_t parseClutterTriangles(const std::string& name);

// The room with about `triangles` triangles (within a few hundred above it). Viewpoints "overview" (the
// default), "shelves", "floor".
Scene makeClutter(uint32_t triangles, uint32_t seed = kClutterDefaultSeed);

// The room's inside, for tests: every object and camera lies in it.
Bounds clutterRoomInterior();

}  // namespace raylab
