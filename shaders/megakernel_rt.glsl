// The rt megakernel (megakernel_rt.rgen, megakernel_rt_atomic.rgen): megakernel.comp with the closest hit
// and the shadow rays through the ray-tracing pipeline; the same shading functions and random streams.
#include "rt_stage.glsl"
#include "path_stage.glsl"

void main() {
  GpuFrame f = FrameBuf(pc.frame).f;
  uint id = gl_LaunchIDEXT.x;
  if (id >= f.pathCount) return;
  uint rng = rngSeed(id, f.frameIndex, 0u, f.seed, RL_RNG_CAMERA);
  PathVars p = cameraPath(f.camera, id / f.sppPerFrame, f.width, f.height, rng);
  uint rays = 0u;
  for (uint b = 0u; b < f.bounceCount && p.alive; ++b) {
    HitRecord hit = rtTraceClosest(f.scene, p.origin, p.direction, 1e30);
    ++rays;
    rng = rngSeed(id, f.frameIndex, b, f.seed, RL_RNG_SHADE);
    shadePath(f.scene, p, hit, b, f.bounceCount, rng);
  }
  f.hits.steps.v[id] = 0u;
  f.results.v[id] = finishedRadiance(p);
  rtCountRays(f.counters, 0u, rays);
}
