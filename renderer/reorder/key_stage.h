// The key stage of the wavefront: between shading and sorting it writes each path's sort key, its index
// as the sort payload and its predicted ray length; after each trace it teaches the length cache the
// distances rays actually travelled. Owns the grid, the length cache, the oracle's scratch distances and
// the pipelines (one per strategy, the strategy being a specialization constant).
//
// Per frame, for bounce b: trace -> recordLearn (b >= 1) -> shade -> recordKeys (if sorting) -> sort ->
// reorder. Each record call ends with a compute barrier, so its writes are visible to the next stage.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <utility>
#include <vector>

#include <glm/glm.hpp>
#include <vulkan/vulkan.h>

#include "renderer/vk/compute_pipeline.h"
#include "renderer/vk/gpu_buffer.h"
#include "renderer/reorder/key_grid.h"
#include "renderer/reorder/length_cache.h"
#include "renderer/settings/settings.h"
#include "renderer/vk/stage_timer.h"
#include "scenes/scene.h"
#include "shaders/key_types.h"

namespace raylab {

class VulkanContext;

// The key parameters that do not depend on the GPU: the grid as given (its spatialBits set for the strategy),
// the fixed length (fixedFactor times the scene's largest extent) and the longest length a key may use
// (cache.lengthMax); the rest of `cache` and oracleT zero. KeyStage adds its cache and buffers to them; a host
// caller (the CPU twins in key_functions.h) can key rays of strategies that learn nothing with them alone.
gpu::GpuKeyParams baseKeyParams(const KeyGrid& grid, const Settings& settings);

class KeyStage {
 public:
  // Keeps a copy of the scene's triangles (the cache is rebuilt from them when the grid changes); a new
  // scene needs a new KeyStage. maxPaths bounds `count` of every record call.
  KeyStage(const VulkanContext& ctx, const Scene& scene, glm::vec3 cameraPos, const Settings& settings,
           uint32_t maxPaths);

  // Applies a change computed once by the caller (call between frames, not while a frame that uses the
  // stage is in flight). Without change.keyParameters (and with the same maxPaths) it only records the
  // settings and camera. Otherwise it rebuilds the grid and cache only when the grid's box or cells change
  // (with clampToCamera a camera move does), clears the cache on change.resetCache, and uploads the
  // parameters once (new thresholds such as ema alpha, gaussian outlier and reset keep what was learned).
  void apply(const Settings& settings, glm::vec3 cameraPos, uint32_t maxPaths, const SettingsChange& change);
  // apply() with the change from the settings the stage holds (for callers without a SettingsChange).
  void configure(const Settings& settings, glm::vec3 cameraPos);

  // New bound on `count` (e.g. a new resolution); keeps what the cache learned.
  void resize(uint32_t maxPaths);

  KeyStrategy strategy() const { return settings_.strategy; }
  // Bits the sort must cover: live keys are < 2^(keyBits-1) and the dead key (all ones) is larger than all
  // of them in these bits. 0 for None (no keys), 1 for dead-last.
  uint32_t keyBits() const;
  const KeyGrid& grid() const { return grid_; }

  // Writes keysOut[i], valuesOut[i] = i and state[stateSet].predictedLength[i] for i < count. None records
  // nothing; oracle first records its trace, timed as "oracle-trace"; the keys are timed as "keys".
  // With `liveArgs` (the live prefix's indirect dispatch size, GpuFrame::live) the keys pass runs over the
  // live prefix only: the caller guarantees that keysOut past it holds dead keys (the last sort left them
  // there, in place). Where most paths have finished this is most of the pass (openings, 8 bounces: 0.029
  // ms a sorted bounce over every slot).
  void recordKeys(VkCommandBuffer cmd, VkDeviceAddress frameBlock, uint32_t stateSet, uint32_t bounce,
                  VkDeviceAddress keysOut, VkDeviceAddress valuesOut, uint32_t count, StageTimer* timer,
                  VkBuffer liveArgs = VK_NULL_HANDLE, VkDeviceSize liveArgsOffset = 0);
  // After the trace of bounce >= 1 (hits in the current set's order, before shading overwrites the rays):
  // folds each live path's hit distance into its ray's cache entry. Only average, ema and gaussian record
  // anything; timed as "learn".
  void recordLearn(VkCommandBuffer cmd, VkDeviceAddress frameBlock, uint32_t stateSet, uint32_t bounce,
                   uint32_t count, StageTimer* timer);

  // Whether the strategy keeps a length cache (average, ema, gaussian); its addresses are zero otherwise.
  bool hasCache() const { return cache_ != nullptr; }
  uint64_t cacheMemoryBytes() const;
  // Entries with samples / entries; downloads the cache (tests; frames measure it on the GPU, DetailStats).
  // 0 without a cache.
  double cacheOccupancy() const;
  uint32_t cacheEntryCount() const;  // 0 without a cache
  uint32_t cacheOutliersRejected() const;
  // Counts the times the cache started from nothing (made, cleared or dropped): a window screenshot compares
  // it across its accumulated frames to tell whether the cache learned only over them, as a headless
  // re-render's does (app/window/learned_history.h).
  uint64_t cacheEpoch() const { return cacheEpoch_; }

  // For tests and stats: the parameters the shaders see, the cache contents, the oracle's distances.
  const gpu::GpuKeyParams& params() const { return params_; }
  // Device address of the GpuKeyParams block (KeyParamsBuf in GLSL), e.g. for a heatmap shader that looks
  // up the cache with keys.glsl's cacheEntry().
  VkDeviceAddress paramsAddress() const { return paramsBuffer_.address(); }
  // shade.comp specialised to this strategy's key function (Settings::fusesKeys), built on first use.
  const ComputePipeline& shadeWithKeys() { return pipeline("shade", settings_.strategy, sizeof(gpu::PathStagePush)); }
  LengthCache::Contents downloadCache() const;
  std::vector<float> downloadOracleLengths(uint32_t count) const;

 private:
  const ComputePipeline& pipeline(const char* shader, KeyStrategy strategy, uint32_t pushBytes);
  void uploadParams();

  const VulkanContext* ctx_;
  uint32_t maxPaths_;
  Bounds sceneBounds_;
  std::vector<Triangle> triangles_;
  Settings settings_;
  glm::vec3 camera_{0.0f};
  KeyGrid grid_;
  std::unique_ptr<LengthCache> cache_;
  uint64_t cacheEpoch_ = 0;
  GpuBuffer oracleT_;
  GpuBuffer paramsBuffer_;
  gpu::GpuKeyParams params_{};
  std::map<std::pair<std::string, KeyStrategy>, ComputePipeline> pipelines_;
};

}  // namespace raylab
