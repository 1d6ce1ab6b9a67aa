// Rounds a size or device address up to a multiple of an alignment the device reports (shader binding
// table strides, acceleration-structure scratch). An alignment of 0 means none.
#pragma once

#include <cstdint>

namespace raylab {

constexpr uint64_t alignUp(uint64_t value, uint64_t alignment) {
  return alignment ? (value + alignment - 1) / alignment * alignment : value;
}

}  // namespace raylab
