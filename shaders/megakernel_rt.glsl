// The rt megakernel (megakernel_rt.rgen, megakernel_rt_atomic.rgen): megakernel.comp with the closest hit
// and the shadow rays through the ray-tracing pipeline; the same shading functions and random streams.
#include "rt_stage.glsl"
#include "path_stage.glsl"
#include "camera_order.h"

void main() {
  GpuFrame f = FrameBuf(pc.frame).f;
  if (gl_LaunchIDEXT.x >= f.pathCount) return;
  const uint id = cameraPathOfSlot(gl_LaunchIDEXT.x, f.width, f.height, f.sppPerFrame);  // generate's order
  uint rng = rngSeed(id, f.frameIndex, 0u, f.seed, RL_RNG_CAMERA);
  PathVars p = cameraPath(f.camera, id / f.sppPerFrame, f.width, f.height, rng);
  uint rays = 0u;
  vec3 radiance = vec3(0.0);
  for (uint b = 0u; b < f.bounceCount && p.alive; ++b) {
    HitRecord hit = rtTraceClosest(f.scene, p.origin, p.direction, 1e30);
    ++rays;
    rng = rngSeed(id, f.frameIndex, b, f.seed, RL_RNG_SHADE);
    p.radiance = vec3(0.0);
    shadePath(f.scene, p, hit, b, f.bounceCount, rng);
    radiance = addBounceRadiance(radiance, b, p.radiance);
  }
  f.hits.steps.v[gl_LaunchIDEXT.x] = 0u;
  f.results.v[id] = vec4(radiance, 1.0);
  rtCountRays(f.counters, 0u, rays);
}
