// Wall time of the window's own steps (UI frames, render steps, presents), in milliseconds.
#pragma once

#include <chrono>

namespace raylab {

inline double msSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace raylab
