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
  bool live = f.state[pc.stateSet].alive.v[i] != 0u;
  rtCountRays(f.counters, pc.bounce * RL_COUNTER_STRIDE, live ? 1u : 0u);
  HitRecord hit;
  hit.t = -1.0;
  hit.triangle = 0u;
  hit.bary = vec2(0.0);
  if (live) {
    GpuPathState s = f.state[pc.stateSet];
    hit = rtTraceClosest(f.scene, s.origin.v[i].xyz, s.direction.v[i].xyz, 1e30);
  }
  f.hits.t.v[i] = hit.t;
  f.hits.triangle.v[i] = hit.triangle;
  f.hits.barycentric.v[i] = hit.bary;
  f.hits.steps.v[i] = 0u;
}
