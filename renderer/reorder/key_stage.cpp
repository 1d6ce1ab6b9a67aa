#include "renderer/reorder/key_stage.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "renderer/reorder/key_functions.h"
#include "renderer/reorder/key_strategies.h"
#include "renderer/vk/vk_context.h"

namespace raylab {

KeyStage::KeyStage(const VulkanContext& ctx, const Scene& scene, glm::vec3 cameraPos, const Settings& settings,
                   uint32_t maxPaths)
    : ctx_(&ctx), maxPaths_(std::max(maxPaths, 1u)), sceneBounds_(scene.bounds()), triangles_(scene.triangles) {
  paramsBuffer_ = GpuBuffer(ctx, sizeof(gpu::GpuKeyParams));
  settings_ = settings;
  camera_ = cameraPos;
  grid_ = makeKeyGrid(sceneBounds_, cameraPos, settings);
  SettingsChange initial;
  initial.keyParameters = true;
  apply(settings, cameraPos, maxPaths_, initial);
}

void KeyStage::configure(const Settings& settings, glm::vec3 cameraPos) {
  SettingsChange change = SettingsChange::between(settings_, settings);
  change.keyParameters = true;  // the camera may have moved
  apply(settings, cameraPos, maxPaths_, change);
}

void KeyStage::resize(uint32_t maxPaths) {
  SettingsChange change;
  change.keyParameters = true;  // the oracle's buffer and the fixed-point unit follow maxPaths
  apply(settings_, camera_, maxPaths, change);
}

void KeyStage::apply(const Settings& settings, glm::vec3 cameraPos, uint32_t maxPaths, const SettingsChange& change) {
  const uint32_t bound = std::max(maxPaths, 1u);
  const bool boundChanged = bound != maxPaths_;  // the length unit and the oracle's buffer follow it
  settings_ = settings;
  camera_ = cameraPos;
  maxPaths_ = bound;
  if (!change.keyParameters && !boundChanged) return;
  KeyGrid grid = makeKeyGrid(sceneBounds_, cameraPos, settings);
  bool gridChanged = !grid.sameCells(grid_);
  bool reset = change.resetCache || gridChanged;
  grid_ = grid;

  if (!strategyInfo(settings.strategy).learnsLengths) {
    if (cache_) ++cacheEpoch_;
    cache_.reset();  // nothing to remember: give the memory back
  } else if (!cache_ || gridChanged) {
    cache_ = std::make_unique<LengthCache>(*ctx_, buildLengthCacheLayout(grid_, triangles_, cameraPos));
    ++cacheEpoch_;
  } else if (reset) {
    cache_->clear();
    ++cacheEpoch_;
  }
  if (settings.strategy == KeyStrategy::Oracle && oracleT_.size() < uint64_t(maxPaths_) * sizeof(float))
    oracleT_ = GpuBuffer(*ctx_, uint64_t(maxPaths_) * sizeof(float));
  if (cache_) {
    grid_.gpu.cacheShift = cache_->layout().cacheShift;
    grid_.gpu.cacheCells = cache_->layout().cacheCells;
  }
  grid_.gpu.spatialBits = spatialKeyBits(settings.strategy, grid_.gpu);
  uploadParams();
}

gpu::GpuKeyParams baseKeyParams(const KeyGrid& grid, const Settings& settings) {
  gpu::GpuKeyParams p{};
  p.grid = grid.gpu;
  float factor = std::clamp(settings.fixedFactor, SettingLimits::kMinFixedFactor, SettingLimits::kMaxFixedFactor);
  if (!(factor >= 0.0f)) factor = 0.5f;  // NaN
  p.cache.lengthMax = std::max(grid.sceneDiagonal, factor * grid.largestExtent) * 1.01f + 1e-6f;
  p.fixedLength = std::min(factor * grid.largestExtent, p.cache.lengthMax);
  return p;
}

void KeyStage::uploadParams() {
  gpu::GpuKeyParams p = baseKeyParams(grid_, settings_);
  const float lengthMax = p.cache.lengthMax;
  p.oracleT = oracleT_.valid() ? oracleT_.address() : 0;
  if (cache_) p.cache = cache_->gpuView();
  p.cache.lengthMax = lengthMax;
  p.cache.unit = lengthCacheUnit(lengthMax, maxPaths_);
  p.cache.invUnit = 1.0f / p.cache.unit;
  p.cache.sigmaFloor = 1e-3f * grid_.sceneDiagonal;
  float alpha = settings_.emaAlpha;
  p.cache.emaAlpha = alpha >= SettingLimits::kMinEmaAlpha ? std::min(alpha, SettingLimits::kMaxEmaAlpha)
                                                          : SettingLimits::kMinEmaAlpha;
  p.cache.gaussOutlier = settings_.gaussOutlier >= 0.0f ? settings_.gaussOutlier : 0.0f;
  p.cache.gaussReset = settings_.gaussReset >= 0.0f ? settings_.gaussReset : 0.0f;
  params_ = p;
  paramsBuffer_.upload(&params_, sizeof(params_));
}

uint32_t KeyStage::keyBits() const { return keyWidth(settings_.strategy, grid_.gpu); }

const ComputePipeline& KeyStage::pipeline(const char* shader, KeyStrategy strategy, uint32_t pushBytes) {
  auto key = std::make_pair(std::string(shader), strategy);
  auto it = pipelines_.find(key);
  if (it == pipelines_.end()) {
    ComputePipeline p(*ctx_, shader, pushBytes, RL_PATH_GROUP_SIZE, {{RL_SPEC_KEY_STRATEGY, strategyId(strategy)}});
    it = pipelines_.emplace(key, std::move(p)).first;
  }
  return it->second;
}

void KeyStage::recordKeys(VkCommandBuffer cmd, VkDeviceAddress frameBlock, uint32_t stateSet, uint32_t bounce,
                          VkDeviceAddress keysOut, VkDeviceAddress valuesOut, uint32_t count, StageTimer* timer,
                          VkBuffer liveArgs, VkDeviceSize liveArgsOffset) {
  KeyStrategy s = settings_.strategy;
  if (s == KeyStrategy::None || count == 0) return;
  if (count > maxPaths_) throw std::invalid_argument("KeyStage::recordKeys: more paths than maxPaths");
  gpu::KeyPush push{frameBlock, paramsBuffer_.address(), keysOut, valuesOut, stateSet, bounce, count, 0};
  if (s == KeyStrategy::Oracle) {
    const ComputePipeline& trace = pipeline("key_oracle", s, sizeof(gpu::KeyPush));
    recordStage(cmd, timer, "oracle-trace", [&] { trace.dispatchThreads(cmd, push, count); });
  }
  const ComputePipeline& keys = pipeline("keys", s, sizeof(gpu::KeyPush));
  recordStage(cmd, timer, "keys", [&] {
    if (liveArgs != VK_NULL_HANDLE)
      keys.dispatchIndirect(cmd, push, liveArgs, liveArgsOffset);
    else
      keys.dispatchThreads(cmd, push, count);
  });
}

void KeyStage::recordLearn(VkCommandBuffer cmd, VkDeviceAddress frameBlock, uint32_t stateSet, uint32_t bounce,
                           uint32_t count, StageTimer* timer) {
  KeyStrategy s = settings_.strategy;
  if (!cache_ || !strategyInfo(s).learnsLengths || bounce == 0 || count == 0) return;
  if (count > maxPaths_) throw std::invalid_argument("KeyStage::recordLearn: more paths than maxPaths");
  const uint32_t every = std::max(1u, settings_.learnEvery);
  gpu::KeyLearnPush push{frameBlock, paramsBuffer_.address(), stateSet, bounce, count, every};
  const ComputePipeline& learn = pipeline("key_learn", s, sizeof(gpu::KeyLearnPush));
  const ComputePipeline& merge = pipeline("key_merge", s, sizeof(gpu::KeyLearnPush));
  recordStage(cmd, timer, "learn", [&] {
    cache_->recordResetTouched(cmd);
    computeBarrier(cmd);
    learn.dispatchThreads(cmd, push, count);
    computeBarrier(cmd);
    // One thread per touched entry: at most one per sampled path.
    merge.dispatchThreads(cmd, push, (count + every - 1) / every);
  });
}

uint64_t KeyStage::cacheMemoryBytes() const { return cache_ ? cache_->memoryBytes() : 0; }

double KeyStage::cacheOccupancy() const { return cache_ ? cache_->occupancy() : 0.0; }

uint32_t KeyStage::cacheEntryCount() const { return cache_ ? cache_->entryCount() : 0; }

uint32_t KeyStage::cacheOutliersRejected() const { return cache_ ? cache_->outliersRejected() : 0; }

LengthCache::Contents KeyStage::downloadCache() const { return cache_ ? cache_->download() : LengthCache::Contents{}; }

std::vector<float> KeyStage::downloadOracleLengths(uint32_t count) const {
  if (!oracleT_.valid()) return {};
  return oracleT_.downloadVector<float>(std::min(count, maxPaths_));
}

}  // namespace raylab
