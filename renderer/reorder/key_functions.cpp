// Twins of shaders/keys.glsl. Keep every expression in the GLSL's order; float literals carry an f so
// nothing is promoted to double; the pragmas stop the compiler from fusing a*b+c into an FMA (which the
// shader forbids with `precise`), whatever -march the project is built with.
#if defined(__clang__)
#pragma clang fp contract(off)
#elif defined(__GNUC__)
#pragma GCC optimize("fp-contract=off")
#endif

#include "renderer/reorder/key_functions.h"

#include "renderer/reorder/key_strategies.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace raylab {


uint32_t pcgHash(uint32_t v) {
  uint32_t state = v * 747796405u + 2891336453u;
  uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

namespace {

float asFloat(uint32_t u) { return std::bit_cast<float>(u); }
uint32_t asUint(float f) { return std::bit_cast<uint32_t>(f); }

uint32_t keyCached(const KeyParams& p, const KeyEnv& env, const KeyPath& path, bool gaussian, float& len) {
  if (!validDirection(path.direction)) {
    len = 0.0f;
    return pointKey(p.grid, path.origin);
  }
  len = p.fixedLength;
  int32_t e = cacheEntry(p.cache, env, p.grid, cellOf(p.grid, path.origin), path.direction);
  if (e >= 0 && static_cast<size_t>(e) < env.entries.size()) {
    const gpu::GpuCacheEntry& c = env.entries[e];
    if (c.count > 0u && !gaussian) len = clampLength(c.mean, p.cache.lengthMax);
    if (c.count > 0u && gaussian) {
      uint32_t rng = rngSeed(path.pathId, env.frameIndex, env.bounce, env.seed, RL_RNG_KEY);
      float sampled = c.mean + c.sigma * gaussianSample(rng);
      len = clampLength(sampled, p.cache.lengthMax);
    }
  }
  return pointKey(p.grid, endPoint(path, len));
}

}  // namespace

uint32_t strategyId(KeyStrategy s) { return strategyInfo(s).shaderId; }


uint32_t spatialKeyBits(KeyStrategy s, const gpu::GpuKeyGrid& g) {
  switch (s) {
    case KeyStrategy::None:
    case KeyStrategy::DeadLast: return 0;
    case KeyStrategy::OriginDirection: return std::min(RL_KEY_MAX_SPATIAL_BITS, g.gridBits + 2 * g.maxAxisBits);
    case KeyStrategy::TwoPoint: return std::min(RL_KEY_TWO_POINT_BITS, 2 * g.gridBits);
    default: return g.gridBits;
  }
}

uint32_t keyWidth(KeyStrategy s, const gpu::GpuKeyGrid& g) {
  return s == KeyStrategy::None ? 0 : spatialKeyBits(s, g) + 1;
}

uint32_t ignoredKeyBits(uint32_t spatialBits, uint32_t sortBits) {
  const uint32_t compared = spatialBits + 1;
  return sortBits > 0 && sortBits < compared ? compared - sortBits : 0;
}

// ---- deterministic arithmetic

float detRcp(float x) {
  float y = asFloat(0x7EF311C3u - asUint(x));
  for (int k = 0; k < 4; ++k) y = y * (2.0f - x * y);
  return y;
}

float detSqrt(float x) {
  if (!(x > 0.0f)) return 0.0f;
  float y = asFloat(0x5F375A86u - (asUint(x) >> 1));
  for (int k = 0; k < 4; ++k) y = y * (1.5f - ((0.5f * x) * y) * y);
  return x * y;
}

float detLn(float x) {
  uint32_t b = asUint(x);
  int e = static_cast<int>((b >> 23) & 0xFFu) - 127;
  float m = asFloat((b & 0x007FFFFFu) | 0x3F800000u);
  if (m > 1.41421354f) {
    m = m * 0.5f;
    e += 1;
  }
  float s = (m - 1.0f) * detRcp(m + 1.0f);
  float s2 = s * s;
  float p = s * (2.0f + s2 * (0.666666687f + s2 * (0.400000006f + s2 * (0.285714298f + s2 * 0.222222224f))));
  return p + static_cast<float>(e) * 0.693147182f;
}

float detCos2Pi(float u) {
  float a = u - std::floor(u);
  if (a > 0.5f) a = 1.0f - a;
  float sgn = 1.0f;
  if (a > 0.25f) {
    a = 0.5f - a;
    sgn = -1.0f;
  }
  float x = a * 6.28318548f;
  float x2 = x * x;
  float c = 1.0f + x2 * (-0.5f + x2 * (0.0416666679f + x2 * (-0.00138888892f + x2 * (2.48015876e-05f +
            x2 * (-2.755732e-07f + x2 * 2.08767559e-09f)))));
  return sgn * c;
}

float gaussianSample(uint32_t& rng) {
  float u1 = 1.0f - rngNext(rng);
  float u2 = rngNext(rng);
  return detSqrt(-2.0f * detLn(u1)) * detCos2Pi(u2);
}

uint32_t rngSeed(uint32_t pathId, uint32_t frame, uint32_t bounce, uint32_t seed, uint32_t stream) {
  return pcgHash(pathId ^ pcgHash(frame ^ pcgHash((bounce * 16u + stream) ^ pcgHash(seed))));
}

float rngNext(uint32_t& state) {
  state = state * 747796405u + 2891336453u;
  uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  word = (word >> 22u) ^ word;
  return static_cast<float>(word >> 8) * (1.0f / 16777216.0f);
}

// ---- grid and bits

bool validDirection(glm::vec3 d) {
  float s = std::abs(d.x) + std::abs(d.y) + std::abs(d.z);
  return s >= 1e-30f && s <= 1e30f;
}

uint32_t cellAxis(float p, float lo, float inv, uint32_t n) {
  float f = (p - lo) * inv;
  return f >= static_cast<float>(n) ? n - 1u : (f > 0.0f ? static_cast<uint32_t>(f) : 0u);
}

glm::uvec3 cellOf(const gpu::GpuKeyGrid& g, glm::vec3 p) {
  return {cellAxis(p.x, g.boundsMin.x, g.invCellSize.x, g.cells.x),
          cellAxis(p.y, g.boundsMin.y, g.invCellSize.y, g.cells.y),
          cellAxis(p.z, g.boundsMin.z, g.invCellSize.z, g.cells.z)};
}

uint32_t interleaveBits(const uint32_t c[6], const uint32_t w[6], uint32_t n, uint32_t maxBits) {
  uint32_t total = 0u;
  for (uint32_t k = 0u; k < n; ++k) total += w[k];
  uint32_t drop = total > maxBits ? total - maxBits : 0u;
  uint32_t key = 0u;
  uint32_t pos = 0u;
  for (uint32_t level = 0u; level < 32u; ++level) {
    bool any = false;
    for (uint32_t k = 0u; k < n; ++k) {
      if (level >= w[k]) continue;
      any = true;
      if (pos >= drop) key |= ((c[k] >> level) & 1u) << (pos - drop);
      ++pos;
    }
    if (!any) break;
  }
  return key;
}

uint32_t mortonCell(const gpu::GpuKeyGrid& g, glm::uvec3 cell) {
  const uint32_t c[6] = {cell.x, cell.y, cell.z, 0u, 0u, 0u};
  const uint32_t w[6] = {g.bits.x, g.bits.y, g.bits.z, 0u, 0u, 0u};
  return interleaveBits(c, w, 3u, 32u);
}

uint32_t pointKey(const gpu::GpuKeyGrid& g, glm::vec3 p) { return mortonCell(g, cellOf(g, p)); }

glm::vec3 endPoint(const KeyPath& path, float len) {
  return {path.origin.x + len * path.direction.x, path.origin.y + len * path.direction.y,
          path.origin.z + len * path.direction.z};
}

uint32_t octant(glm::vec3 d) {
  return (d.x < 0.0f ? 1u : 0u) | (d.y < 0.0f ? 2u : 0u) | (d.z < 0.0f ? 4u : 0u);
}

namespace {
uint32_t quantizeUnit(float x, uint32_t bits) {
  float n = static_cast<float>(1u << bits);
  float f = x * n;
  return f >= n ? (1u << bits) - 1u : (f > 0.0f ? static_cast<uint32_t>(f) : 0u);
}
}  // namespace

glm::uvec2 octahedralCell(glm::vec3 d, uint32_t bitsU, uint32_t bitsV) {
  float inv = detRcp(std::abs(d.x) + std::abs(d.y) + std::abs(d.z));
  float nx = d.x * inv;
  float ny = d.y * inv;
  float nz = d.z * inv;
  float u = nx;
  float v = ny;
  if (nz < 0.0f) {
    u = (1.0f - std::abs(ny)) * (nx >= 0.0f ? 1.0f : -1.0f);
    v = (1.0f - std::abs(nx)) * (ny >= 0.0f ? 1.0f : -1.0f);
  }
  u = u * 0.5f + 0.5f;
  v = v * 0.5f + 0.5f;
  return {quantizeUnit(u, bitsU), quantizeUnit(v, bitsV)};
}

float clampLength(float x, float maxLength) { return x > 0.0f ? std::min(x, maxLength) : 0.0f; }

uint32_t hashCell(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7FEB352Du;
  x ^= x >> 15;
  x *= 0x846CA68Bu;
  x ^= x >> 16;
  return x;
}

uint32_t cacheCellIndex(const gpu::GpuKeyGrid& g, glm::uvec3 cell) {
  glm::uvec3 cc = cell >> g.cacheShift;
  return cc.x + g.cacheCells.x * (cc.y + g.cacheCells.y * cc.z);
}

int32_t cacheEntry(const gpu::GpuLengthCache& c, const KeyEnv& env, const gpu::GpuKeyGrid& g, glm::uvec3 cell,
                   glm::vec3 dir) {
  if (env.slotKeys.empty()) return -1;
  uint32_t key = cacheCellIndex(g, cell) + 1u;
  uint32_t slot = hashCell(key) & c.slotMask;
  for (uint32_t probe = 0u; probe <= c.slotMask; ++probe) {
    uint32_t k = env.slotKeys[slot];
    if (k == key) return static_cast<int32_t>(env.slotValues[slot] * RL_OCTANTS + octant(dir));
    if (k == 0u) return -1;
    slot = (slot + 1u) & c.slotMask;
  }
  return -1;
}

// ---- the strategies

uint32_t keyDeadLast(const KeyParams&, const KeyEnv&, const KeyPath&, float& len) {
  len = -1.0f;
  return 0u;
}

uint32_t keyFixed(const KeyParams& p, const KeyEnv&, const KeyPath& path, float& len) {
  if (!validDirection(path.direction)) {
    len = 0.0f;
    return pointKey(p.grid, path.origin);
  }
  len = p.fixedLength;
  return pointKey(p.grid, endPoint(path, len));
}

uint32_t keyAverage(const KeyParams& p, const KeyEnv& env, const KeyPath& path, float& len) {
  return keyCached(p, env, path, false, len);
}
uint32_t keyEma(const KeyParams& p, const KeyEnv& env, const KeyPath& path, float& len) {
  return keyCached(p, env, path, false, len);
}
uint32_t keyGaussian(const KeyParams& p, const KeyEnv& env, const KeyPath& path, float& len) {
  return keyCached(p, env, path, true, len);
}

uint32_t keyOrigin(const KeyParams& p, const KeyEnv&, const KeyPath& path, float& len) {
  len = -1.0f;
  return pointKey(p.grid, path.origin);
}

uint32_t keyDirection(const KeyParams& p, const KeyEnv&, const KeyPath& path, float& len) {
  len = -1.0f;
  if (!validDirection(path.direction)) return 0u;
  uint32_t bitsU = (p.grid.gridBits + 1u) / 2u;
  uint32_t bitsV = p.grid.gridBits / 2u;
  glm::uvec2 d = octahedralCell(path.direction, bitsU, bitsV);
  const uint32_t c[6] = {d.x, d.y, 0u, 0u, 0u, 0u};
  const uint32_t w[6] = {bitsU, bitsV, 0u, 0u, 0u, 0u};
  return interleaveBits(c, w, 2u, 32u);
}

uint32_t keyOriginDirection(const KeyParams& p, const KeyEnv&, const KeyPath& path, float& len) {
  len = -1.0f;
  glm::uvec3 o = cellOf(p.grid, path.origin);
  uint32_t m = p.grid.maxAxisBits;
  glm::uvec2 d = validDirection(path.direction) ? octahedralCell(path.direction, m, m) : glm::uvec2(0u);
  const uint32_t c[6] = {o.x, o.y, o.z, d.x, d.y, 0u};
  const uint32_t w[6] = {p.grid.bits.x, p.grid.bits.y, p.grid.bits.z, m, m, 0u};
  return interleaveBits(c, w, 5u, RL_KEY_MAX_SPATIAL_BITS);
}

uint32_t keyTwoPoint(const KeyParams& p, const KeyEnv&, const KeyPath& path, float& len) {
  len = validDirection(path.direction) ? p.fixedLength : 0.0f;
  glm::uvec3 o = cellOf(p.grid, path.origin);
  glm::uvec3 e = len > 0.0f ? cellOf(p.grid, endPoint(path, len)) : o;
  const uint32_t c[6] = {o.x, o.y, o.z, e.x, e.y, e.z};
  const uint32_t w[6] = {p.grid.bits.x, p.grid.bits.y, p.grid.bits.z, p.grid.bits.x, p.grid.bits.y, p.grid.bits.z};
  return interleaveBits(c, w, 6u, RL_KEY_TWO_POINT_BITS);
}

uint32_t keyOracle(const KeyParams& p, const KeyEnv&, const KeyPath& path, float& len) {
  if (!validDirection(path.direction)) {
    len = 0.0f;
    return pointKey(p.grid, path.origin);
  }
  len = path.oracleT > 0.0f && path.oracleT < 1e30f ? path.oracleT : p.fixedLength;
  return pointKey(p.grid, endPoint(path, len));
}

uint32_t computeKey(uint32_t strategy, const KeyParams& p, const KeyEnv& env, const KeyPath& path, uint32_t alive,
                    float& len) {
  len = -1.0f;
  if (alive == 0u) return RL_DEAD_KEY;
  switch (strategy) {
    case RL_KEY_DEAD_LAST: return keyDeadLast(p, env, path, len);
    case RL_KEY_FIXED: return keyFixed(p, env, path, len);
    case RL_KEY_AVERAGE: return keyAverage(p, env, path, len);
    case RL_KEY_EMA: return keyEma(p, env, path, len);
    case RL_KEY_GAUSSIAN: return keyGaussian(p, env, path, len);
    case RL_KEY_ORIGIN: return keyOrigin(p, env, path, len);
    case RL_KEY_DIRECTION: return keyDirection(p, env, path, len);
    case RL_KEY_ORIGIN_DIRECTION: return keyOriginDirection(p, env, path, len);
    case RL_KEY_TWO_POINT: return keyTwoPoint(p, env, path, len);
    case RL_KEY_ORACLE: return keyOracle(p, env, path, len);
    default: return 0u;
  }
}

}  // namespace raylab
