// Built-in scenes generated in code: no asset files, deterministic for a given set of parameters, so
// tests, benchmarks and screenshots can name them and always get the same triangles.
#pragma once

#include <cstdint>

#include "scenes/scene.h"

namespace raylab {

// The procedural scenes' angles.
inline constexpr float kPi = 3.14159265358979f;

struct TempleParams {
  uint32_t seed = 1;       // jitters building heights, broken columns, lamps, rubble
  float size = 1.0f;       // uniform scale; 1 gives about 150 x 40 x 150 units
  int columnsPerSide = 8;  // columns in each colonnade row
  int detail = 1;          // tessellation of cylinders and arches, and the amount of rubble
};

// The lab's default scene: a walled temple courtyard open to the sky, with colonnades, arches, a
// narrow alley between high walls and a roofed hall with windows, lit by the sky and a few lamps.
// Its viewpoints span the cases a ray-reordering study needs: "alley" (primary rays nearly all hit),
// "hall" (enclosed, rays scatter most), "openings" (many primary rays escape), "overview".
Scene makeTemple(const TempleParams& p = {});

// The classic Cornell box, closed but for the front; viewpoint "front".
Scene makeCornell();

// White-furnace test: a closed icosphere of radius 1 around the origin, every triangle pure Lambert
// with baseColor = albedo and emission = emission, no sky. Seen from the centre, every path bounces
// forever, so the mean radiance after B bounces is emission * sum_{k<B} albedo^k. Viewpoint "center".
Scene makeFurnace(float albedo = 0.5f, float emission = 0.5f, int subdivisions = 3);

}  // namespace raylab
