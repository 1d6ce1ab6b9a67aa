#include "renderer/vk/empty_dispatch.h"

#include <algorithm>
#include <vector>

#include "renderer/vk/compute_pipeline.h"
#include "renderer/vk/gpu_timer.h"
#include "renderer/vk/vk_context.h"
#include "shaders/shared_types.h"

namespace raylab {

std::optional<double> measureEmptyDispatchUs(const VulkanContext& ctx, uint32_t dispatches, uint32_t submissions) {
  if (!ctx.info().timestamps || dispatches == 0) return std::nullopt;
  const ComputePipeline empty(ctx, "empty", sizeof(gpu::PathStagePush), RL_PATH_GROUP_SIZE);
  const gpu::PathStagePush push{0, 0, 0};
  GpuTimer timer(ctx, 2);
  auto run = [&](VkCommandBuffer cmd, uint32_t n) {
    timer.begin(cmd, "empty");
    for (uint32_t i = 0; i < n; ++i) {
      empty.dispatchGroups(cmd, push, 1);
      computeBarrier(cmd);
    }
    timer.end(cmd);
  };
  std::vector<double> perDispatchUs;
  // The first submission warms up (first use of the pipeline, clocks) and is not kept.
  for (uint32_t s = 0; s <= submissions; ++s) {
    ctx.submitAndWait([&](VkCommandBuffer cmd) {
      timer.reset(cmd);
      run(cmd, dispatches);
      run(cmd, 2 * dispatches);
    });
    const std::vector<StageTime> t = timer.collect();
    if (s > 0 && t.size() == 2) perDispatchUs.push_back(std::max(0.0, t[1].ms - t[0].ms) * 1e3 / dispatches);
  }
  if (perDispatchUs.empty()) return std::nullopt;
  std::nth_element(perDispatchUs.begin(), perDispatchUs.begin() + perDispatchUs.size() / 2, perDispatchUs.end());
  return perDispatchUs[perDispatchUs.size() / 2];
}

}  // namespace raylab
