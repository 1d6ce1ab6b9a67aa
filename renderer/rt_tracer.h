// The rt tracer: the scene's acceleration structures and the ray-tracing pipelines that replace the compute
// trace and shade stages (trace_rt, shade_rt) and the megakernel (megakernel_rt, or megakernel_ser with
// Shader Execution Reordering). Made by PathTracer when Settings::tracer is rt; it records the same stages
// with the same push constants and the same hit layout, so everything around them works unchanged.
#pragma once

#include <map>
#include <memory>
#include <string>

#include "renderer/settings/settings.h"
#include "renderer/vk/acceleration_structure.h"
#include "renderer/vk/rt_pipeline.h"
#include "shaders/key_types.h"

namespace raylab {

class VulkanContext;
class GpuSceneData;
struct DeviceInfo;

// Empty when `settings` can run on the device; else why not, naming the missing extensions or features.
std::string unsupportedSettings(const DeviceInfo& device, const Settings& settings);

class RtTracer {
 public:
  RtTracer(const VulkanContext& ctx, const GpuSceneData& scene);

  VkDeviceAddress tlasAddress() const { return structures_.tlasAddress(); }
  uint64_t accelerationStructureBytes() const { return structures_.bytes(); }

  void traceRays(VkCommandBuffer cmd, const gpu::PathStagePush& push, uint32_t paths) const;
  void shade(VkCommandBuffer cmd, const gpu::PathStagePush& push, uint32_t paths) const;
  void megakernel(VkCommandBuffer cmd, const gpu::PathStagePush& push, uint32_t paths) const;
  // SER: reorder by hit, and with hintStrategy != None by the top bits of that strategy's key.
  void serMegakernel(VkCommandBuffer cmd, const gpu::RtSerPush& push, KeyStrategy hintStrategy, uint32_t paths);

 private:
  const VulkanContext& ctx_;
  AccelerationStructures structures_;
  RtPipeline trace_, shade_, megakernel_;
  std::map<KeyStrategy, RtPipeline> ser_;  // made on first use, per hint strategy
};

}  // namespace raylab
