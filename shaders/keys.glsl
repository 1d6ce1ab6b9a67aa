// The key functions, one per strategy, each the twin of the function of the same name in
// renderer/reorder/key_functions.cpp. The GPU keys must equal the C++ keys bit for bit (tests/gpu/test_key_gpu.cpp), so:
// every float result is `precise` (no fused multiply-add the C++ side would not do), expressions are
// written in the same order on both sides, and division, sqrt, log and cos are replaced by deterministic
// Newton iterations and polynomials (Vulkan lets those built-ins be approximate, differently per device).
// Needs key_types.h and rng.glsl.
#ifndef RAYLAB_KEYS_GLSL
#define RAYLAB_KEYS_GLSL

struct KeyPath {
  vec3 origin;
  vec3 direction;
  uint pathId;
  float oracleT;  // oracle strategy only: the true hit distance, negative on a miss
};

// Per-dispatch values the key functions need besides the path and the parameters.
struct KeyEnv {
  uint frameIndex;
  uint bounce;
  uint seed;
};

// ---- deterministic arithmetic (only +, -, *, comparisons and bit operations)

// 1/x for x in [1e-30, 1e30]: bit-trick guess, four Newton steps (the error squares each step).
float detRcp(float x) {
  precise float y = uintBitsToFloat(0x7EF311C3u - floatBitsToUint(x));
  for (int k = 0; k < 4; ++k) y = y * (2.0 - x * y);
  return y;
}

// sqrt(x) for x >= 0 as x / sqrt(x) with the inverse square root by Newton steps.
float detSqrt(float x) {
  if (!(x > 0.0)) return 0.0;
  precise float y = uintBitsToFloat(0x5F375A86u - (floatBitsToUint(x) >> 1));
  for (int k = 0; k < 4; ++k) y = y * (1.5 - ((0.5 * x) * y) * y);
  precise float r = x * y;
  return r;
}

// ln(x) for finite x > 0: x = m * 2^e with m in [0.707, 1.414), ln m = 2 atanh(s), s = (m-1)/(m+1).
float detLn(float x) {
  uint b = floatBitsToUint(x);
  int e = int((b >> 23) & 0xFFu) - 127;
  precise float m = uintBitsToFloat((b & 0x007FFFFFu) | 0x3F800000u);
  if (m > 1.41421354) {
    m = m * 0.5;
    e += 1;
  }
  precise float s = (m - 1.0) * detRcp(m + 1.0);
  precise float s2 = s * s;
  precise float p = s * (2.0 + s2 * (0.666666687 + s2 * (0.400000006 + s2 * (0.285714298 + s2 * 0.222222224))));
  precise float r = p + float(e) * 0.693147182;
  return r;
}

// cos(2 pi u), folded to [0, pi/2] and a Taylor polynomial to x^12 (error below 1e-8).
float detCos2Pi(float u) {
  precise float a = u - floor(u);
  if (a > 0.5) a = 1.0 - a;
  float sgn = 1.0;
  if (a > 0.25) {
    a = 0.5 - a;
    sgn = -1.0;
  }
  precise float x = a * 6.28318548;
  precise float x2 = x * x;
  precise float c = 1.0 + x2 * (-0.5 + x2 * (0.0416666679 + x2 * (-0.00138888892 + x2 * (2.48015876e-05 +
                    x2 * (-2.755732e-07 + x2 * 2.08767559e-09)))));
  precise float r = sgn * c;
  return r;
}

// Standard normal by Box-Muller from two uniforms of the key stream.
float gaussianSample(inout uint rng) {
  precise float u1 = 1.0 - rngNext(rng);  // (0, 1]: the log stays finite
  float u2 = rngNext(rng);
  precise float r = detSqrt(-2.0 * detLn(u1)) * detCos2Pi(u2);
  return r;
}

// ---- grid and bits

// NaN fails both comparisons, infinities the second: such directions get a fallback key, never a NaN.
bool validDirection(vec3 d) {
  precise float s = abs(d.x) + abs(d.y) + abs(d.z);
  return s >= 1e-30 && s <= 1e30;
}

// Written so NaN lands in cell 0 and +-inf in the edge cells without a NaN test the compiler may drop.
uint cellAxis(float p, float lo, float inv, uint n) {
  precise float f = (p - lo) * inv;
  return f >= float(n) ? n - 1u : (f > 0.0 ? uint(f) : 0u);
}

uvec3 cellOf(GpuKeyGrid g, vec3 p) {
  return uvec3(cellAxis(p.x, g.boundsMin.x, g.invCellSize.x, g.cells.x),
               cellAxis(p.y, g.boundsMin.y, g.invCellSize.y, g.cells.y),
               cellAxis(p.z, g.boundsMin.z, g.invCellSize.z, g.cells.z));
}

// Interleaves the low w[k] bits of c[k], least significant level first; at each level only components
// with bits left take part (unequal widths: the longer axes are split alone at the top, like a k-d tree).
// When the total exceeds maxBits the finest levels are dropped, keeping the coarse ordering.
uint interleaveBits(uint c[6], uint w[6], uint n, uint maxBits) {
  uint total = 0u;
  for (uint k = 0u; k < n; ++k) total += w[k];
  uint drop = total > maxBits ? total - maxBits : 0u;
  uint key = 0u;
  uint pos = 0u;
  for (uint level = 0u; level < 32u; ++level) {
    bool any = false;
    for (uint k = 0u; k < n; ++k) {
      if (level >= w[k]) continue;
      any = true;
      if (pos >= drop) key |= ((c[k] >> level) & 1u) << (pos - drop);
      ++pos;
    }
    if (!any) break;
  }
  return key;
}

uint mortonCell(GpuKeyGrid g, uvec3 cell) {
  uint c[6] = uint[6](cell.x, cell.y, cell.z, 0u, 0u, 0u);
  uint w[6] = uint[6](g.bits.x, g.bits.y, g.bits.z, 0u, 0u, 0u);
  return interleaveBits(c, w, 3u, 32u);
}

uint pointKey(GpuKeyGrid g, vec3 p) { return mortonCell(g, cellOf(g, p)); }

vec3 endPoint(KeyPath path, float len) {
  precise vec3 e = path.origin + len * path.direction;
  return e;
}

// Octant of a direction: one bit per negative component (NaN components count as positive).
uint octant(vec3 d) { return (d.x < 0.0 ? 1u : 0u) | (d.y < 0.0 ? 2u : 0u) | (d.z < 0.0 ? 4u : 0u); }

uint quantizeUnit(float x, uint bits) {
  float n = float(1u << bits);
  precise float f = x * n;
  return f >= n ? (1u << bits) - 1u : (f > 0.0 ? uint(f) : 0u);
}

// Octahedral map of a valid direction to [0,1]^2 (area-fair enough, no trigonometry), quantized per axis.
uvec2 octahedralCell(vec3 d, uint bitsU, uint bitsV) {
  precise float inv = detRcp(abs(d.x) + abs(d.y) + abs(d.z));
  precise float nx = d.x * inv;
  precise float ny = d.y * inv;
  precise float nz = d.z * inv;
  precise float u = nx;
  precise float v = ny;
  if (nz < 0.0) {
    u = (1.0 - abs(ny)) * (nx >= 0.0 ? 1.0 : -1.0);
    v = (1.0 - abs(nx)) * (ny >= 0.0 ? 1.0 : -1.0);
  }
  u = u * 0.5 + 0.5;
  v = v * 0.5 + 0.5;
  return uvec2(quantizeUnit(u, bitsU), quantizeUnit(v, bitsV));
}

float clampLength(float x, float maxLength) { return x > 0.0 ? min(x, maxLength) : 0.0; }

// ---- length cache lookup (the table is built on the host by renderer/reorder/length_cache.cpp, same hash)

uint hashCell(uint x) {
  x ^= x >> 16;
  x *= 0x7FEB352Du;
  x ^= x >> 15;
  x *= 0x846CA68Bu;
  x ^= x >> 16;
  return x;
}

// Entry index of (the cache cell holding `cell`, the octant of `dir`), or -1 when the cell is unoccupied.
int cacheEntry(GpuLengthCache c, GpuKeyGrid g, uvec3 cell, vec3 dir) {
  uvec3 cc = cell >> g.cacheShift;
  uint key = cc.x + g.cacheCells.x * (cc.y + g.cacheCells.y * cc.z) + 1u;
  uint slot = hashCell(key) & c.slotMask;
  for (uint probe = 0u; probe <= c.slotMask; ++probe) {
    uint k = c.slotKeys.v[slot];
    if (k == key) return int(c.slotValues.v[slot] * RL_OCTANTS + octant(dir));
    if (k == 0u) return -1;
    slot = (slot + 1u) & c.slotMask;
  }
  return -1;
}

// ---- the strategies (dead paths never reach them: computeKey gives those RL_DEAD_KEY)

uint keyDeadLast(GpuKeyParams P, KeyEnv env, KeyPath path, out float len) {
  len = -1.0;
  return 0u;
}

uint keyFixed(GpuKeyParams P, KeyEnv env, KeyPath path, out float len) {
  if (!validDirection(path.direction)) {
    len = 0.0;
    return pointKey(P.grid, path.origin);
  }
  len = P.fixedLength;
  return pointKey(P.grid, endPoint(path, len));
}

// Average, EMA and Gaussian: the learned length of (origin cell, octant), the fixed length when unknown.
uint keyCached(GpuKeyParams P, KeyEnv env, KeyPath path, bool gaussian, out float len) {
  if (!validDirection(path.direction)) {
    len = 0.0;
    return pointKey(P.grid, path.origin);
  }
  len = P.fixedLength;
  int e = cacheEntry(P.cache, P.grid, cellOf(P.grid, path.origin), path.direction);
  if (e >= 0) {
    GpuCacheEntry c = P.cache.entries.v[e];
    if (c.count > 0u && !gaussian) len = clampLength(c.mean, P.cache.lengthMax);
    if (c.count > 0u && gaussian) {
      uint rng = rngSeed(path.pathId, env.frameIndex, env.bounce, env.seed, RL_RNG_KEY);
      precise float sampled = c.mean + c.sigma * gaussianSample(rng);
      len = clampLength(sampled, P.cache.lengthMax);
    }
  }
  return pointKey(P.grid, endPoint(path, len));
}

uint keyAverage(GpuKeyParams P, KeyEnv env, KeyPath path, out float len) { return keyCached(P, env, path, false, len); }
uint keyEma(GpuKeyParams P, KeyEnv env, KeyPath path, out float len) { return keyCached(P, env, path, false, len); }
uint keyGaussian(GpuKeyParams P, KeyEnv env, KeyPath path, out float len) { return keyCached(P, env, path, true, len); }

uint keyOrigin(GpuKeyParams P, KeyEnv env, KeyPath path, out float len) {
  len = -1.0;
  return pointKey(P.grid, path.origin);
}

uint keyDirection(GpuKeyParams P, KeyEnv env, KeyPath path, out float len) {
  len = -1.0;
  if (!validDirection(path.direction)) return 0u;
  uint bitsU = (P.grid.gridBits + 1u) / 2u;
  uint bitsV = P.grid.gridBits / 2u;
  uvec2 d = octahedralCell(path.direction, bitsU, bitsV);
  uint c[6] = uint[6](d.x, d.y, 0u, 0u, 0u, 0u);
  uint w[6] = uint[6](bitsU, bitsV, 0u, 0u, 0u, 0u);
  return interleaveBits(c, w, 2u, 32u);
}

uint keyOriginDirection(GpuKeyParams P, KeyEnv env, KeyPath path, out float len) {
  len = -1.0;
  uvec3 o = cellOf(P.grid, path.origin);
  uint m = P.grid.maxAxisBits;
  uvec2 d = validDirection(path.direction) ? octahedralCell(path.direction, m, m) : uvec2(0u);
  uint c[6] = uint[6](o.x, o.y, o.z, d.x, d.y, 0u);
  uint w[6] = uint[6](P.grid.bits.x, P.grid.bits.y, P.grid.bits.z, m, m, 0u);
  return interleaveBits(c, w, 5u, RL_KEY_MAX_SPATIAL_BITS);
}

uint keyTwoPoint(GpuKeyParams P, KeyEnv env, KeyPath path, out float len) {
  len = validDirection(path.direction) ? P.fixedLength : 0.0;
  uvec3 o = cellOf(P.grid, path.origin);
  uvec3 e = len > 0.0 ? cellOf(P.grid, endPoint(path, len)) : o;
  uint c[6] = uint[6](o.x, o.y, o.z, e.x, e.y, e.z);
  uint w[6] = uint[6](P.grid.bits.x, P.grid.bits.y, P.grid.bits.z, P.grid.bits.x, P.grid.bits.y, P.grid.bits.z);
  return interleaveBits(c, w, 6u, RL_KEY_TWO_POINT_BITS);
}

// A miss has no hit point: its end point is the fixed length along the ray.
uint keyOracle(GpuKeyParams P, KeyEnv env, KeyPath path, out float len) {
  if (!validDirection(path.direction)) {
    len = 0.0;
    return pointKey(P.grid, path.origin);
  }
  len = path.oracleT > 0.0 && path.oracleT < 1e30 ? path.oracleT : P.fixedLength;
  return pointKey(P.grid, endPoint(path, len));
}

uint computeKey(uint strategy, GpuKeyParams P, KeyEnv env, KeyPath path, uint alive, out float len) {
  len = -1.0;
  if (alive == 0u) return RL_DEAD_KEY;
  switch (strategy) {
    case RL_KEY_DEAD_LAST: return keyDeadLast(P, env, path, len);
    case RL_KEY_FIXED: return keyFixed(P, env, path, len);
    case RL_KEY_AVERAGE: return keyAverage(P, env, path, len);
    case RL_KEY_EMA: return keyEma(P, env, path, len);
    case RL_KEY_GAUSSIAN: return keyGaussian(P, env, path, len);
    case RL_KEY_ORIGIN: return keyOrigin(P, env, path, len);
    case RL_KEY_DIRECTION: return keyDirection(P, env, path, len);
    case RL_KEY_ORIGIN_DIRECTION: return keyOriginDirection(P, env, path, len);
    case RL_KEY_TWO_POINT: return keyTwoPoint(P, env, path, len);
    case RL_KEY_ORACLE: return keyOracle(P, env, path, len);
  }
  return 0u;
}

#endif
