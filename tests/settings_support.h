// A Settings value shared by the settings tests on the CPU and the GPU.
#pragma once

#include <cmath>

#include "renderer/settings.h"

namespace raylab::test {

// A Settings value with every field away from its default, as a user might leave it.
inline Settings unusualSettings() {
  Settings s;
  s.scene = "cornell";
  s.view = "front";
  s.width = 33, s.height = 17;
  s.bounces = 3, s.sppPerFrame = 2, s.frames = 4, s.seed = 9, s.exposure = 1.5f;
  s.strategy = KeyStrategy::Gaussian;
  s.sort = SortAlgorithm::Bitonic;
  s.grid.automatic = false;
  s.grid.cells = {8, 16, 32};
  s.clampToCamera = true, s.clampDistance = 12.5f;
  s.fixedFactor = 0.25f, s.emaAlpha = 0.5f, s.gaussOutlier = 2.0f, s.gaussReset = INFINITY;
  s.countSimt = true;
  return s;
}

}  // namespace raylab::test
