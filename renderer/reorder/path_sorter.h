// Sorts the paths between bounces when a key strategy is on: sort keys (KeyStage), the GPU sort, the
// live-prefix count and the gather of the path state into the other ping-pong set (timed together as the
// "reorder" stage). Also the length-cache learning after a trace. (Detailed statistics of the keys and
// their predictions are GPU reductions of their own: renderer/detail_stats.h.)
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
#include "renderer/settings/settings.h"
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
  // After the trace of `bounce` whose rays were keyed and sorted: the learn stage (strategies that learn
  // lengths, bounces >= 1; nothing otherwise: KeyStage::recordLearn).
  void recordLearn(VkCommandBuffer cmd, const PathBuffers& buffers, uint32_t stateSet, uint32_t bounce,
                   StageTimer* timer);
  // After shading `bounce`: the keys of the next rays (in buffers.keys, current set order), unless shade made
  // them (`madeInShade`, Settings::fusesKeys).
  void recordKeys(VkCommandBuffer cmd, const PathBuffers& buffers, uint32_t stateSet,
                  uint32_t bounce, bool madeInShade, StageTimer* timer);
  // Sorts the live prefix's pairs in place (buffers.keys, buffers.values).
  void recordSort(VkCommandBuffer cmd, const PathBuffers& buffers, uint32_t paths, StageTimer* timer);
  // The reorder after recordSort: live count and gather into the other set, which it returns. With
  // Settings::fusesGather the next trace does this instead (trace.comp's gathering variant).
  uint32_t recordGather(VkCommandBuffer cmd, const PathBuffers& buffers, uint32_t paths, uint32_t stateSet,
                        StageTimer* timer);
  // Shade that also makes the keys of the rays it writes (shade.comp with the strategy's key function).
  const ComputePipeline& shadeWithKeys() { return keys_.shadeWithKeys(); }
  // Adds key width, cache and sort memory to the stats.
  void finishFrame(FrameStats& stats) const;

  const KeyStage& keys() const { return keys_; }

 private:
  void makeSorter(const Settings& settings);

  const VulkanContext& ctx_;
  KeyStage keys_;
  std::unique_ptr<GpuSorter> sorter_;
  uint32_t maxPaths_;
  uint32_t sortBits_ = 0;  // Settings::sortBits
  ComputePipeline gather_;
};

}  // namespace raylab
