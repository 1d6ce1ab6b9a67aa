#include "renderer/path_buffers.h"

#include "renderer/settings/settings.h"
#include "renderer/vk/vk_context.h"

namespace raylab {

static_assert(RL_MAX_BOUNCES == SettingLimits::kMaxBounces);

PathBuffers::PathBuffers(const VulkanContext& ctx, uint32_t width, uint32_t height, uint32_t spp)
    : pathCount(width * height * spp), pixelCount(width * height) {
  const VkDeviceSize n = pathCount;
  for (auto& set : state)
    for (int a = 0; a < RL_STATE_ARRAY_COUNT; ++a) set[a] = GpuBuffer(ctx, n * 16);  // one vec4 a path
  hitT = GpuBuffer(ctx, n * 4);
  hitTriangle = GpuBuffer(ctx, n * 4);
  hitBarycentric = GpuBuffer(ctx, n * 8);
  hitSteps = GpuBuffer(ctx, n * 4);
  results = GpuBuffer(ctx, n * 16);
  accumulation = GpuBuffer(ctx, VkDeviceSize(pixelCount) * 16);
  image = GpuBuffer(ctx, VkDeviceSize(pixelCount) * 4);
  counters = GpuBuffer(ctx, counterBytes(RL_MAX_BOUNCES));
  counterHistory = GpuBuffer(ctx, counterBytes(RL_MAX_BOUNCES), MemoryKind::HostVisible);
  keys = GpuBuffer(ctx, n * 4);
  values = GpuBuffer(ctx, n * 4);
  live = GpuBuffer(ctx, kLiveBlockBytes * (1 + RL_MAX_BOUNCES));
  frameBlock = GpuBuffer(ctx, sizeof(gpu::GpuFrame));
}

gpu::GpuFrame PathBuffers::addresses() const {
  gpu::GpuFrame f{};
  for (int s = 0; s < 2; ++s) {
    f.state[s].origin = state[s][RL_STATE_ORIGIN].address();
    f.state[s].direction = state[s][RL_STATE_DIRECTION].address();
    f.state[s].throughput = state[s][RL_STATE_THROUGHPUT].address();
  }
  f.hits.t = hitT.address();
  f.hits.triangle = hitTriangle.address();
  f.hits.barycentric = hitBarycentric.address();
  f.hits.steps = hitSteps.address();
  f.results = results.address();
  f.accumulation = accumulation.address();
  f.image = image.address();
  f.counters = counters.address();
  f.live = live.address();
  f.sortKeys = keys.address();
  f.sortValues = values.address();
  f.pathCount = pathCount;
  return f;
}

uint64_t PathBuffers::pathStateBytes() const {
  uint64_t total = 0;
  for (const auto& set : state)
    for (const GpuBuffer& b : set) total += b.size();
  return total + hitT.size() + hitTriangle.size() + hitBarycentric.size() + hitSteps.size() + results.size() +
         keys.size() + values.size();
}

}  // namespace raylab
