// The procedural scenes' random numbers: splitmix64, whose output is fixed by the seed on every platform and
// standard library (std:: distributions are not), so a seed names the same geometry everywhere.
#pragma once

#include <cstdint>

namespace raylab {

class SplitMixRng {
 public:
  explicit SplitMixRng(uint64_t seed) : state_(seed * 0x9E3779B97F4A7C15ull + 0x632BE59BD9B4E019ull) {}
  uint64_t next() {
    uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  float uniform(float lo, float hi) {
    return lo + (hi - lo) * static_cast<float>(next() >> 40) * (1.0f / 16777216.0f);
  }

 private:
  uint64_t state_;
};

}  // namespace raylab
