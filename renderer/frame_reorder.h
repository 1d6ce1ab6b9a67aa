// Everything between shade and the next trace when sorting is on: sort keys (KeyStage), the GPU sort, and
// the gather of the path state into the other ping-pong set. Also the length-cache learning after a trace.
#pragma once

#include <cstdint>
#include <memory>

#include <glm/glm.hpp>
#include <vulkan/vulkan.h>

#include "renderer/compute_pipeline.h"
#include "renderer/frame_stats.h"
#include "renderer/settings.h"
#include "scenes/scene.h"

namespace raylab {

class VulkanContext;
class StageTimer;
struct PathBuffers;

class FrameReorder {
 public:
  FrameReorder(const VulkanContext& ctx, const Scene& scene, const Settings& settings, glm::vec3 cameraPos);
  ~FrameReorder();

  // Rebuilds the grid and caches when the settings or camera need it.
  void configure(const Settings& settings, glm::vec3 cameraPos, bool resetCaches);
  void resize(uint32_t maxPaths);

  void recordLearn(VkCommandBuffer cmd, VkDeviceAddress frame, uint32_t stateSet, uint32_t bounce, uint32_t count,
                   StageTimer* timer);
  // Keys, sort and gather; returns the state set that holds the reordered paths.
  uint32_t recordReorder(VkCommandBuffer cmd, VkDeviceAddress frame, uint32_t stateSet, uint32_t bounce,
                         uint32_t count, const PathBuffers& buffers, StageTimer* timer);
  // Adds key width, cache and sort memory (and, in detailed mode, prediction accuracy) to the stats.
  void finishFrame(FrameStats& stats, bool detailed);

 private:
  const VulkanContext& ctx_;
  Settings settings_;
  ComputePipeline gather_;
};

}  // namespace raylab
