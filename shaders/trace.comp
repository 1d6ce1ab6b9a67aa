#version 460
// Closest-hit traversal of every live path's ray; records the hit and the loop iteration count.
// The counting variant (simt_counting.glsl, spec constant 1) also counts active lanes per traversal iteration.
// The gathering variant (spec constant 2, Settings::fusion gather) is also the reorder after a sort: it runs
// over every slot, moves path sortValues[i] of the current set into slot i of the other set (the 48-byte
// gather of gather_path_state.comp) and traces the ray it moved, so the ray is not read a second time and
// the reorder needs no dispatch and barrier of its own. It finds the new live prefix as the gather did.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#include "spec_ids.h"
#include "shared_types.h"
#include "simt_counting.glsl"
#include "path_shading.glsl"
#include "path_stage.glsl"
#include "live_paths.glsl"
#include "reorder_slot.glsl"
#include "dispatch_index.glsl"

layout(constant_id = RL_SPEC_FUSES_GATHER) const bool kFusesGather = false;

void main() {
  GpuFrame f = FrameBuf(pc.frame).f;
  gCounters = f.counters;
  gCounterBase = pc.bounce * RL_COUNTER_STRIDE;
  uint i = flatInvocationIndex();
  vec3 origin, direction;
  bool live;
  if (kFusesGather) {
    // Dispatched over every slot (not the live count, which this dispatch rewrites).
    if (i >= f.pathCount) return;
    live = reorderSlot(f, pc.stateSet, i, origin, direction);
    countRays(live ? 1u : 0u);
    if (!live) return;  // an empty slot: reorderSlot gave it no traversal steps
  } else {
    uint count = f.live.v[RL_LIVE_COUNT];
    live = i < count && pathRay(f.state[pc.stateSet], i, origin, direction);
    countRays(live ? 1u : 0u);
    if (i >= count) return;
  }
  HitRecord hit = noHit();
  if (live) hit = traceClosest(f.scene, origin, direction, 1e30);
  storeHit(f.hits, i, hit);
}
