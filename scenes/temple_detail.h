// The scene-scale family: the temple with finer and finer geometry in its hall, from about 10^4 to 3*10^7
// triangles, so that one viewpoint can be measured while the BVH grows from a few hundred kilobytes to far
// beyond a GPU's L2. The added geometry is the same at every size (a flagstone pavement, carved reliefs on
// the walls, fluted sleeves on the columns, rubble in the aisles), only sampled more finely, so paths
// bounce alike and what changes with the triangle count is the BVH, not the light transport.
//
// Named `temple-detail:N` (N the triangle count, e.g. temple-detail:2e6) on the command line, in sidecars and
// in bench cases; plain `temple-detail` is kTempleDetailDefaultTriangles.
#pragma once

#include <cstdint>
#include <string>

#include "scenes/scene.h"

namespace raylab {

inline constexpr const char* kTempleDetailName = "temple-detail";
inline constexpr uint32_t kTempleDetailMinTriangles = 10000;     // the temple itself has about 7,400
inline constexpr uint32_t kTempleDetailMaxTriangles = 30000000;  // about 2 GB of scene on the host
inline constexpr uint32_t kTempleDetailDefaultTriangles = 100000;

// True for "temple-detail" and "temple-detail:<anything>": names the family claims, good size or not.
bool isTempleDetailName(const std::string& name);
// The triangle count a family name asks for. Throws std::invalid_argument with the accepted range for a
// size that is not a number in [kTempleDetailMinTriangles, kTempleDetailMaxTriangles] ("1e6" and
// "1000000" both work; fractions are rounded).
uint32_t parseTempleDetailTriangles(const std::string& name);

// The temple (default parameters) plus the hall's detail, sampled so that the scene has about
// `triangles` triangles (within a few percent above 2*10^4; the coarsest sampling below). Deterministic:
// the same count gives the same triangles. Viewpoints are the temple's, "hall" first.
Scene makeTempleDetail(uint32_t triangles);

}  // namespace raylab
