#version 460
// Detailed statistics, key prediction: over a bounce's rays after their trace, each live path with a
// predicted length (the key stage's, carried in its state through the reorder) and a hit adds its error
// |predicted - actual length| / scene diagonal (the distance between the estimated and the actual end point:
// directions are unit) to a fixed-point sum and a histogram (for the median), and whether both end points
// fall in the same grid cell. Errors are formed with exact float operations (a subtraction and a
// multiplication, `precise`), so the plain C++ twin (renderer/detail_sums.cpp) gives the same integers.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_EXT_shader_subgroup_extended_types_int64 : require
#include "spec_ids.h"
#include "detail_types.h"
#include "rng.glsl"
#include "keys.glsl"
#include "path_state.glsl"
#include "atomic_add_64.glsl"

layout(local_size_x_id = RL_SPEC_GROUP_SIZE) in;  // RL_DETAIL_GROUP_SIZE
layout(push_constant, scalar) uniform Push { DetailPush pc; };

shared uint bins[RL_DETAIL_ERROR_BINS];

// The histogram bin of an error >= 0: its float's exponent and top mantissa bits, offset to the range; bin 0
// holds the errors below it (renderer/detail_sums.cpp's errorBin, the twin).
uint errorBin(float e) {
  const int first = (127 + RL_DETAIL_BIN_MIN_EXPONENT) << RL_DETAIL_BIN_MANTISSA_BITS;
  const int b = int(floatBitsToUint(e) >> (23u - RL_DETAIL_BIN_MANTISSA_BITS)) - first + 1;
  return uint(clamp(b, 0, int(RL_DETAIL_ERROR_BINS) - 1));
}

void main() {
  for (uint b = gl_LocalInvocationID.x; b < RL_DETAIL_ERROR_BINS; b += RL_DETAIL_GROUP_SIZE) bins[b] = 0u;
  barrier();
  FrameBuf frame = FrameBuf(pc.frame);
  GpuPathState state = frame.f.state[pc.stateSet];
  GpuKeyGrid grid = KeyParamsBuf(pc.keyParams).p.grid;
  uint live = 0u, evaluated = 0u, misses = 0u, sameCell = 0u;
  uint64_t errorSum = 0ul;
  for (uint i = gl_GlobalInvocationID.x; i < pc.count; i += gl_NumWorkGroups.x * RL_DETAIL_GROUP_SIZE) {
    KeyPath path;
    if (!pathRay(state, i, path.origin, path.direction)) continue;
    ++live;
    const float predicted = pathPredictedLength(state, i);
    if (!(predicted >= 0.0)) continue;
    const float t = frame.f.hits.t.v[i];
    if (!(t > 0.0 && t < 1e30)) {
      ++misses;
      continue;
    }
    precise float error = abs(predicted - t) * pc.invDiagonal;
    if (!(error < 1e30)) continue;  // an infinite prediction: no meaningful distance
    ++evaluated;
    errorSum += uint64_t(min(error, float(RL_DETAIL_ERROR_MAX)) * float(1u << RL_DETAIL_ERROR_FRACTION_BITS));
    atomicAdd(bins[errorBin(error)], 1u);
    if (cellOf(grid, endPoint(path, predicted)) == cellOf(grid, endPoint(path, t))) ++sameCell;
  }
  live = subgroupAdd(live);
  evaluated = subgroupAdd(evaluated);
  misses = subgroupAdd(misses);
  sameCell = subgroupAdd(sameCell);
  errorSum = subgroupAdd(errorSum);
  if (subgroupElect() && live > 0u) {
    atomicAdd(pc.sums.s.livePaths, live);
    atomicAdd(pc.sums.s.evaluated, evaluated);
    atomicAdd(pc.sums.s.misses, misses);
    atomicAdd(pc.sums.s.sameCell, sameCell);
    ATOMIC_ADD_64(pc.sums.s.errorLo, pc.sums.s.errorHi, errorSum);
  }
  barrier();
  for (uint b = gl_LocalInvocationID.x; b < RL_DETAIL_ERROR_BINS; b += RL_DETAIL_GROUP_SIZE)
    if (bins[b] > 0u) atomicAdd(pc.sums.s.errorBins[b], bins[b]);
}
