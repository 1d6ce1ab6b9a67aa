#include "renderer/path_buffers.h"

#include "renderer/vk_context.h"

namespace raylab {

PathBuffers::PathBuffers(const VulkanContext& ctx, uint32_t width, uint32_t height, uint32_t spp, uint32_t bounces)
    : pathCount(width * height * spp), pixelCount(width * height) {
  const VkDeviceSize n = pathCount;
  const VkDeviceSize elementBytes[7] = {16, 16, 16, 16, 4, 4, 4};
  for (auto& set : state)
    for (int a = 0; a < 7; ++a) set[a] = GpuBuffer(ctx, n * elementBytes[a]);
  hitT = GpuBuffer(ctx, n * 4);
  hitTriangle = GpuBuffer(ctx, n * 4);
  hitBarycentric = GpuBuffer(ctx, n * 8);
  hitSteps = GpuBuffer(ctx, n * 4);
  results = GpuBuffer(ctx, n * 16);
  accumulation = GpuBuffer(ctx, VkDeviceSize(pixelCount) * 16);
  image = GpuBuffer(ctx, VkDeviceSize(pixelCount) * 4);
  counters = GpuBuffer(ctx, kCounterCount * 4);
  counterHistory = GpuBuffer(ctx, VkDeviceSize(kCounterCount) * 4 * (bounces + 1), MemoryKind::HostVisible);
  keys = GpuBuffer(ctx, n * 4);
  values = GpuBuffer(ctx, n * 4);
  live = GpuBuffer(ctx, 4 * 4);
  frameBlock = GpuBuffer(ctx, sizeof(gpu::GpuFrame));
}

gpu::GpuFrame PathBuffers::addresses() const {
  gpu::GpuFrame f{};
  for (int s = 0; s < 2; ++s) {
    f.state[s].origin = state[s][0].address();
    f.state[s].direction = state[s][1].address();
    f.state[s].throughput = state[s][2].address();
    f.state[s].radiance = state[s][3].address();
    f.state[s].pathId = state[s][4].address();
    f.state[s].alive = state[s][5].address();
    f.state[s].predictedLength = state[s][6].address();
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
