// Preamble of the wavefront stages (compute, and the rt tracer's ray-generation shaders): push constants, the frame block, and loading/storing one path's
// state from the structure-of-arrays buffers of the current set.
#ifndef RAYLAB_PATH_STAGE_GLSL
#define RAYLAB_PATH_STAGE_GLSL

#include "shared_types.h"
#include "path_shading.glsl"

#ifndef RL_RAY_TRACING_STAGE
layout(local_size_x_id = 0) in;  // ray-generation shaders have a launch size instead
#endif
layout(push_constant, scalar) uniform Push { PathStagePush pc; };

PathVars loadPath(GpuPathState s, uint i) {
  PathVars p;
  vec4 o = s.origin.v[i];
  p.origin = o.xyz;
  p.pdf = o.w;
  p.direction = s.direction.v[i].xyz;
  p.throughput = s.throughput.v[i].xyz;
  p.radiance = s.radiance.v[i].xyz;
  p.alive = s.alive.v[i] != 0u;
  return p;
}

void storePath(GpuPathState s, uint i, PathVars p) {
  s.origin.v[i] = vec4(p.origin, p.pdf);
  s.direction.v[i] = vec4(p.direction, 0.0);
  s.throughput.v[i] = vec4(p.throughput, 0.0);
  s.radiance.v[i] = vec4(p.radiance, 0.0);
  s.alive.v[i] = p.alive ? 1u : 0u;
}

#endif
