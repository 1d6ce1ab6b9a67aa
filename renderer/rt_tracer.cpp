#include "renderer/rt_tracer.h"

#include "renderer/gpu_scene.h"
#include "renderer/reorder/key_functions.h"
#include "renderer/vk/vk_context.h"

namespace raylab {

std::string unsupportedSettings(const DeviceInfo& device, const Settings& settings) {
  if (settings.tracer == Tracer::Rt && !device.rayTracing)
    return "--tracer rt needs VK_KHR_acceleration_structure and VK_KHR_ray_tracing_pipeline; " + device.name +
           " lacks " + device.rayTracingMissing;
  if (settings.tracer == Tracer::Rt && settings.ser != Ser::Off && !device.ser)
    return "--ser " + toString(settings.ser) + " needs VK_NV_ray_tracing_invocation_reorder; " + device.name + " lacks " +
           device.serMissing;
  return "";
}

RtTracer::RtTracer(const VulkanContext& ctx, const GpuSceneData& scene)
    : ctx_(ctx),
      structures_(ctx, scene.bvhOrderVertices()),
      trace_(ctx, ctx.info().subgroupsInRayGen ? "trace_rt" : "trace_rt_atomic", sizeof(gpu::PathStagePush)),
      shade_(ctx, "shade_rt", sizeof(gpu::PathStagePush)),
      megakernel_(ctx, ctx.info().subgroupsInRayGen ? "megakernel_rt" : "megakernel_rt_atomic",
                  sizeof(gpu::PathStagePush)) {}

void RtTracer::traceRays(VkCommandBuffer cmd, const gpu::PathStagePush& push, uint32_t paths) const {
  trace_.traceRays(cmd, push, paths);
}

void RtTracer::shade(VkCommandBuffer cmd, const gpu::PathStagePush& push, uint32_t paths) const {
  shade_.traceRays(cmd, push, paths);
}

void RtTracer::megakernel(VkCommandBuffer cmd, const gpu::PathStagePush& push, uint32_t paths) const {
  megakernel_.traceRays(cmd, push, paths);
}

void RtTracer::serMegakernel(VkCommandBuffer cmd, const gpu::RtSerPush& push, KeyStrategy hintStrategy,
                             uint32_t paths) {
  auto it = ser_.find(hintStrategy);
  if (it == ser_.end())
    it = ser_.emplace(hintStrategy, RtPipeline(ctx_, "megakernel_ser", sizeof(gpu::RtSerPush),
                                               {{RL_SPEC_KEY_STRATEGY, strategyId(hintStrategy)}}))
             .first;
  it->second.traceRays(cmd, push, paths);
}

}  // namespace raylab
