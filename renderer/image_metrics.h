// Image error metrics shared by the benchmark and the tests.
#pragma once

#include <vector>

#include <glm/glm.hpp>

namespace raylab {

// Relative MSE of `image` against `reference`: the mean over pixels and channels of
// (x - r)^2 / (r^2 + 0.01); the 0.01 keeps near-black reference pixels from dominating.
// Returns -1 when the sizes differ or the images are empty.
double relativeMse(const std::vector<glm::vec3>& image, const std::vector<glm::vec3>& reference);

}  // namespace raylab
