#version 460
// The oracle strategy's extra trace: the true hit distance of each live path's next ray, found with the
// same traversal as the trace stage, before the sort. A separate dispatch so its cost is timed on its own
// ("oracle-trace"); keys.comp turns the distance into the key.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#include "spec_ids.h"
#include "key_types.h"
#include "bvh_traverse.glsl"
#include "rng.glsl"
#include "keys.glsl"
#include "path_state.glsl"
#include "dispatch_index.glsl"

layout(local_size_x_id = RL_SPEC_GROUP_SIZE) in;
layout(push_constant, scalar) uniform Push { KeyPush pc; };

void main() {
  uint i = flatInvocationIndex();
  if (i >= pc.count) return;
  FrameBuf frame = FrameBuf(pc.frame);
  GpuPathState state = frame.f.state[pc.stateSet];
  GpuKeyParams params = KeyParamsBuf(pc.params).p;
  float t = -1.0;
  vec3 origin, dir;
  bool alive = pathRay(state, i, origin, dir);
  if (alive && validDirection(dir)) t = traceClosest(frame.f.scene, origin, dir, 1e30).t;
  params.oracleT.v[i] = t;
}
