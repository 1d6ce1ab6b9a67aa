// StageTimer on Vulkan timestamp queries: each named scope writes a timestamp pair; after the frame's
// submission completes, collect() turns them into StageTime entries (stage name, bounce, milliseconds).
#pragma once

#include <string>
#include <vector>

#include "renderer/frame_stats.h"
#include "renderer/vk/gpu_buffer.h"
#include "renderer/vk/stage_timer.h"

namespace raylab {

class VulkanContext;

class GpuTimer : public StageTimer {
 public:
  GpuTimer(const VulkanContext& ctx, uint32_t maxScopes = 512);
  ~GpuTimer() override;
  GpuTimer(const GpuTimer&) = delete;
  GpuTimer& operator=(const GpuTimer&) = delete;

  // Starts a new set of scopes: records the query reset.
  void reset(VkCommandBuffer cmd);
  void setBounce(int bounce) { bounce_ = bounce; }
  void begin(VkCommandBuffer cmd, std::string_view stage) override;
  void end(VkCommandBuffer cmd) override;
  // Reads the results of the scopes since reset(); call after the commands completed.
  std::vector<StageTime> collect();
  // GPU time from the first scope's start to the last scope's end, as of the last collect().
  double spanMs() const { return spanMs_; }
  // Scopes begun since reset(); collect() returns one entry per scope, in this order.
  uint32_t scopeCount() const { return static_cast<uint32_t>(scopes_.size()); }

 private:
  struct Scope {
    std::string stage;
    int bounce;
    uint32_t first;
  };
  const VulkanContext& ctx_;
  VkQueryPool pool_ = VK_NULL_HANDLE;
  GpuBuffer settle_;  // CPU devices: where settle() copies each timestamp read, one slot per query
  void settle(VkCommandBuffer cmd, uint32_t query);
  uint32_t capacity_ = 0;
  uint32_t used_ = 0;
  int bounce_ = -1;
  double spanMs_ = 0.0;
  std::vector<Scope> scopes_;
  std::vector<uint32_t> open_;
};

}  // namespace raylab
