#include "renderer/vk/dispatch_size.h"

#include <string>

#include "renderer/vk/vk_check.h"
#include "shaders/dispatch_grid.h"

namespace raylab {

DispatchSize dispatchSizeFor(uint64_t threads, uint32_t groupSize, uint32_t rowGroups, uint32_t maxRows) {
  const uint64_t groups = (threads + groupSize - 1) / groupSize;
  const uint64_t rows = RL_GRID_Y(groups, uint64_t(rowGroups));
  if (rows > maxRows)
    throw VulkanError(std::to_string(threads) + " threads need " + std::to_string(rows) + " rows of " +
                      std::to_string(rowGroups) + " work groups; the device launches at most " + std::to_string(maxRows));
  return {static_cast<uint32_t>(RL_GRID_X(groups, uint64_t(rowGroups))), static_cast<uint32_t>(rows)};
}

}  // namespace raylab
