// Sorts the paths between bounces when a key strategy is on: sort keys (KeyStage), the GPU sort, the
// live-prefix count and the gather of the path state into the other ping-pong set (timed together as the
// "reorder" stage). Also the length-cache learning after a trace, and, in the detailed mode, the readbacks
// that measure prediction accuracy.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>
#include <vulkan/vulkan.h>

#include "renderer/vk/compute_pipeline.h"
#include "renderer/frame_stats.h"
#include "renderer/path_buffers.h"
#include "renderer/vk/gpu_buffer.h"
#include "renderer/reorder/gpu_sort.h"
#include "renderer/reorder/key_stage.h"
#include "renderer/settings.h"
#include "scenes/scene.h"

namespace raylab {

class VulkanContext;
class StageTimer;
struct PathBuffers;

class PathSorter {
 public:
  PathSorter(const VulkanContext& ctx, const Scene& scene, const Settings& settings, glm::vec3 cameraPos,
               uint32_t maxPaths);
  ~PathSorter();

  // Applies a change PathTracer computed (new path bound, key grid and caches as `change` says) and makes
  // the sorter the settings ask for; the sorter's scratch is only held while sorting.
  void apply(const Settings& settings, glm::vec3 cameraPos, uint32_t maxPaths, const SettingsChange& change);

  // Every call works on all the frame's paths (buffers.pathCount).
  // A frame starts: no readback of an earlier (possibly abandoned) frame counts for it.
  void beginFrame();
  // After the trace of `bounce` whose rays were keyed and sorted (`keyed`; a call without does nothing):
  // the learn stage, and in detailed mode the accuracy readbacks. Bounces without keys have no prediction,
  // so they have no accuracy figures (null in the stats, never stale readbacks).
  void recordAfterTrace(VkCommandBuffer cmd, const PathBuffers& buffers, uint32_t stateSet,
                        uint32_t bounce, bool keyed, bool detailed, StageTimer* timer);
  // After shading `bounce`: the keys of the next rays (in buffers.keys, current set order), unless shade made
  // them (`madeInShade`, Settings::fusesKeys); the detailed readback of the keys either way.
  void recordKeys(VkCommandBuffer cmd, const PathBuffers& buffers, uint32_t stateSet,
                  uint32_t bounce, bool madeInShade, bool detailed, StageTimer* timer);
  // Sorts the live prefix's pairs in place (buffers.keys, buffers.values).
  void recordSort(VkCommandBuffer cmd, const PathBuffers& buffers, uint32_t paths, StageTimer* timer);
  // The reorder after recordSort: live count and gather into the other set, which it returns. With
  // Settings::fusesGather the next trace does this instead (trace.comp's gathering variant).
  uint32_t recordGather(VkCommandBuffer cmd, const PathBuffers& buffers, uint32_t paths, uint32_t stateSet,
                        StageTimer* timer);
  // Shade that also makes the keys of the rays it writes (shade.comp with the strategy's key function).
  const ComputePipeline& shadeWithKeys() { return keys_.shadeWithKeys(); }
  // Adds key width, cache and sort memory and, in detailed mode, prediction accuracy to the stats.
  void finishFrame(FrameStats& stats, bool detailed);

  const KeyStage& keys() const { return keys_; }

 private:
  struct Capture;  // host-visible copies of one bounce's rays, predictions, hits and keys

  void makeSorter(const Settings& settings);
  Capture& captureOf(uint32_t bounce, uint32_t framePaths);

  const VulkanContext& ctx_;
  KeyStage keys_;
  std::unique_ptr<GpuSorter> sorter_;
  uint32_t maxPaths_;
  uint32_t sortBits_ = 0;  // Settings::sortBits
  ComputePipeline gather_;
  std::vector<std::unique_ptr<Capture>> captures_;
};

}  // namespace raylab
