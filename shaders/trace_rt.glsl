// The rt tracer's trace stage (trace_rt.rgen, trace_rt_atomic.rgen): trace.comp with the closest hit from
// traceRayEXT. One launch index per path of the current set; hits go where the shade stage reads them.
// Traversal steps are written as 0: the driver's traversal has no loop we can count (the statistics that
// need it say "not available with the rt tracer").
#include "rt_stage.glsl"
#include "path_stage.glsl"

void main() {
  GpuFrame f = FrameBuf(pc.frame).f;
  uint i = gl_LaunchIDEXT.x;
  if (i >= f.live.v[RL_LIVE_COUNT]) return;
  GpuPathState s = f.state[pc.stateSet];
  vec3 origin, direction;
  bool live = pathRay(s, i, origin, direction);
  rtCountRays(f.counters, pc.bounce * RL_COUNTER_STRIDE, live ? 1u : 0u);
  HitRecord hit = noHit();
  if (live) hit = rtTraceClosest(f.scene, origin, direction, 1e30);
  storeHit(f.hits, i, hit);
}
