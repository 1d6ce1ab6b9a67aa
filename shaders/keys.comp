#version 460
// Sort keys of the current path set: key, payload (the path's index) and the predicted ray length, one
// thread per path. The strategy is specialization constant 1 (RL_KEY_*), so each variant compiles to
// only its own key function (keys.glsl, twin of renderer/reorder/key_functions.cpp).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#include "spec_ids.h"
#include "key_types.h"
#include "rng.glsl"
#include "keys.glsl"
#include "path_state.glsl"
#include "dispatch_index.glsl"

layout(local_size_x_id = RL_SPEC_GROUP_SIZE) in;
layout(constant_id = RL_SPEC_KEY_STRATEGY) const uint kStrategy = RL_KEY_FIXED;
layout(push_constant, scalar) uniform Push { KeyPush pc; };

void main() {
  uint i = flatInvocationIndex();
  if (i >= pc.count) return;
  FrameBuf frame = FrameBuf(pc.frame);
  // Slots past the live prefix of the last sort hold finished paths (gather_path_state.comp): their key is
  // the dead key without reading their state, and the sort reads the same bound. (PathSorter dispatches
  // this pass over the live prefix only, where the sort already left dead keys behind it.)
  if (i >= frame.f.live.v[RL_LIVE_COUNT]) {
    UintBuf(pc.keys).v[i] = RL_DEAD_KEY;
    UintBuf(pc.values).v[i] = i;
    return;
  }
  GpuPathState state = frame.f.state[pc.stateSet];
  GpuKeyParams params = KeyParamsBuf(pc.params).p;
  KeyPath path;
  uint alive = pathRay(state, i, path.origin, path.direction, path.pathId) ? 1u : 0u;
  path.oracleT = kStrategy == RL_KEY_ORACLE && alive != 0u ? params.oracleT.v[i] : -1.0;
  KeyEnv env;
  env.frameIndex = frame.f.frameIndex;
  env.bounce = pc.bounce;
  env.seed = frame.f.seed;
  float len;
  uint key = computeKey(kStrategy, params, env, path, alive, len);
  UintBuf(pc.keys).v[i] = key;
  UintBuf(pc.values).v[i] = i;
  setPathPredictedLength(state, i, len);
}
