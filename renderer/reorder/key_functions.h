// C++ twins of the GLSL key functions in shaders/keys.glsl: same names, same arguments, same operation
// order, so a key computed here equals the GPU's bit for bit (tests/gpu/test_key_gpu.cpp checks it). The
// renderer never calls these per path; they are the reference the shaders are tested against, and the
// grid helpers (cellOf, mortonCell) are shared with the accuracy figures and the cache builder.
#pragma once

#include <cstdint>
#include <span>

#include <glm/glm.hpp>

#include "renderer/settings/settings.h"
#include "shaders/key_types.h"

namespace raylab {

struct KeyPath {
  glm::vec3 origin{0.0f};
  glm::vec3 direction{0.0f, 0.0f, 1.0f};
  uint32_t pathId = 0;
  float oracleT = -1.0f;  // oracle strategy only: the true hit distance, negative on a miss
};

// What the GLSL functions reach through buffer references in GpuKeyParams (the cache contents) plus the
// per-dispatch values. The spans may be empty for strategies that use no cache.
struct KeyEnv {
  uint32_t frameIndex = 0;
  uint32_t bounce = 0;
  uint32_t seed = 0;
  std::span<const uint32_t> slotKeys;
  std::span<const uint32_t> slotValues;
  std::span<const gpu::GpuCacheEntry> entries;
};

// Strategy id as the shaders see it (specialization constant 1): RL_KEY_*.
uint32_t strategyId(KeyStrategy s);
// Bits the live keys of `s` use on `grid`; the key width the sort must cover is this + 1 (the dead key is
// all ones, so it stays the largest in those bits), or 0 for None.
uint32_t spatialKeyBits(KeyStrategy s, const gpu::GpuKeyGrid& grid);
uint32_t keyWidth(KeyStrategy s, const gpu::GpuKeyGrid& grid);
// Low key bits the sort ignores for Settings::sortBits (0: all compared): it compares the live keys'
// `spatialBits` bits and its own clamp bit for the dead key (gpu_sort.h), and keeps the top `sortBits` of them.
uint32_t ignoredKeyBits(uint32_t spatialBits, uint32_t sortBits);

// Deterministic arithmetic (twins of keys.glsl; only +, -, *, comparisons and bit operations).
float detRcp(float x);
float detSqrt(float x);
float detLn(float x);
float detCos2Pi(float u);
float gaussianSample(uint32_t& rng);
// rng.glsl's integer hash.
uint32_t pcgHash(uint32_t v);
uint32_t rngSeed(uint32_t pathId, uint32_t frame, uint32_t bounce, uint32_t seed, uint32_t stream);
float rngNext(uint32_t& state);

// Grid and bits.
bool validDirection(glm::vec3 d);
uint32_t cellAxis(float p, float lo, float inv, uint32_t n);
glm::uvec3 cellOf(const gpu::GpuKeyGrid& g, glm::vec3 p);
uint32_t interleaveBits(const uint32_t c[6], const uint32_t w[6], uint32_t n, uint32_t maxBits);
uint32_t mortonCell(const gpu::GpuKeyGrid& g, glm::uvec3 cell);
uint32_t pointKey(const gpu::GpuKeyGrid& g, glm::vec3 p);
glm::vec3 endPoint(const KeyPath& path, float len);
uint32_t octant(glm::vec3 d);
glm::uvec2 octahedralCell(glm::vec3 d, uint32_t bitsU, uint32_t bitsV);
float clampLength(float x, float maxLength);
uint32_t hashCell(uint32_t x);
// Linear index of the cache cell that holds key cell `cell` (the hash table's key is this + 1).
uint32_t cacheCellIndex(const gpu::GpuKeyGrid& g, glm::uvec3 cell);
int32_t cacheEntry(const gpu::GpuLengthCache& c, const KeyEnv& env, const gpu::GpuKeyGrid& g, glm::uvec3 cell,
                   glm::vec3 dir);

// The strategies; `len` receives the predicted ray length (-1: the strategy predicts none).
using KeyParams = gpu::GpuKeyParams;
uint32_t keyDeadLast(const KeyParams& p, const KeyEnv& env, const KeyPath& path, float& len);
uint32_t keyFixed(const KeyParams& p, const KeyEnv& env, const KeyPath& path, float& len);
uint32_t keyAverage(const KeyParams& p, const KeyEnv& env, const KeyPath& path, float& len);
uint32_t keyEma(const KeyParams& p, const KeyEnv& env, const KeyPath& path, float& len);
uint32_t keyGaussian(const KeyParams& p, const KeyEnv& env, const KeyPath& path, float& len);
uint32_t keyOrigin(const KeyParams& p, const KeyEnv& env, const KeyPath& path, float& len);
uint32_t keyDirection(const KeyParams& p, const KeyEnv& env, const KeyPath& path, float& len);
uint32_t keyOriginDirection(const KeyParams& p, const KeyEnv& env, const KeyPath& path, float& len);
uint32_t keyTwoPoint(const KeyParams& p, const KeyEnv& env, const KeyPath& path, float& len);
uint32_t keyOracle(const KeyParams& p, const KeyEnv& env, const KeyPath& path, float& len);
// Dead paths (alive == 0) get RL_DEAD_KEY and len -1; others the strategy's key.
uint32_t computeKey(uint32_t strategy, const KeyParams& p, const KeyEnv& env, const KeyPath& path, uint32_t alive,
                    float& len);

}  // namespace raylab
