// The one place that knows the path-state and hit layouts (GpuPathState, GpuHits in shared_types.h):
// every stage that reads or writes a path's state or its hit does it through these accessors, so a new
// layout, or another stage that traces (e.g. a hardware ray-tracing backend), follows by changing or
// calling only these. Needs shared_types.h; the whole-path and hit accessors need path_shading.glsl
// (PathVars, HitRecord) included first.
//
// Layout (RL_STATE_*): three 16-byte elements per path,
//   origin     = (ray origin xyz, pdf of the BSDF sample that made the ray)
//   direction  = (ray direction xyz, path id bits; RL_DEAD_PATH once the path finished)
//   throughput = (path throughput xyz, predicted ray length of the key stage, -1: none)
// Radiance is not part of the state: each bounce's contribution goes to results[pathId] (pathAddRadiance).
#ifndef RAYLAB_PATH_STATE_GLSL
#define RAYLAB_PATH_STATE_GLSL

// The direction element is read and written as a whole uvec4: the path id's bits must never pass through
// a float register (small ids are denormals as floats, which a device may flush to zero), and a component
// access through the cast reference (directionBits(s).v[i].w) read the wrong component on lavapipe.
UVec4Buf directionBits(GpuPathState s) { return UVec4Buf(s.direction); }

// ---- rays (trace, keys, learn, oracle)
vec3 pathOrigin(GpuPathState s, uint i) { return s.origin.v[i].xyz; }
vec3 pathDirection(GpuPathState s, uint i) { return uintBitsToFloat(directionBits(s).v[i].xyz); }
// RL_DEAD_PATH when the path has finished.
uint pathId(GpuPathState s, uint i) {
  uvec4 d = directionBits(s).v[i];
  return d.w;
}
bool pathAlive(GpuPathState s, uint i) { return pathId(s, i) != RL_DEAD_PATH; }
// The ray of path i and whether it is alive, from one 16-byte load of the direction and one of the origin.
bool pathRay(GpuPathState s, uint i, out vec3 origin, out vec3 direction) {
  uvec4 d = directionBits(s).v[i];
  direction = uintBitsToFloat(d.xyz);
  origin = s.origin.v[i].xyz;
  return d.w != RL_DEAD_PATH;
}
// The same, with the path id (RL_DEAD_PATH once finished) from that one load of the direction element.
bool pathRay(GpuPathState s, uint i, out vec3 origin, out vec3 direction, out uint id) {
  uvec4 d = directionBits(s).v[i];
  direction = uintBitsToFloat(d.xyz);
  origin = s.origin.v[i].xyz;
  id = d.w;
  return d.w != RL_DEAD_PATH;
}
float pathPredictedLength(GpuPathState s, uint i) { return s.throughput.v[i].w; }
void setPathPredictedLength(GpuPathState s, uint i, float len) { s.throughput.v[i].w = len; }
// A finished path's ray is never read again: the whole element is overwritten (no read).
void markPathFinished(GpuPathState s, uint i) { directionBits(s).v[i] = uvec4(0u, 0u, 0u, RL_DEAD_PATH); }

// A slot behind the live prefix after a reorder: finished, and no traversal steps. The next trace does not
// visit it, but the warp statistics read every slot's steps (stale ones counted paths traced bounces ago).
void markSlotEmpty(GpuPathState dst, GpuHits h, uint i) {
  markPathFinished(dst, i);
  h.steps.v[i] = 0u;
}

// ---- the reorder: path j of src becomes path i of dst (three 16-byte copies); gives the moved path's ray
// and whether it is alive.
bool movePath(GpuPathState dst, uint i, GpuPathState src, uint j, out vec3 origin, out vec3 direction) {
  vec4 o = src.origin.v[j];
  uvec4 d = directionBits(src).v[j];
  dst.origin.v[i] = o;
  directionBits(dst).v[i] = d;
  dst.throughput.v[i] = src.throughput.v[j];
  origin = o.xyz;
  direction = uintBitsToFloat(d.xyz);
  return d.w != RL_DEAD_PATH;
}

// ---- radiance: results[id] holds the sum of the path's bounce contributions (w = 1). Bounce 0 writes it
// (no read: every path is shaded at bounce 0), later bounces add only a non-zero contribution. Adding zero
// would not change the sum, so the sum is the one the megakernel forms in registers. Non-finite sums are
// dropped by the accumulate pass.
void pathAddRadiance(RL_REF(Vec4Buf) results, uint id, uint bounce, vec3 radiance) {
  if (bounce == 0u) {
    results.v[id] = vec4(radiance, 1.0);
  } else if (radiance != vec3(0.0)) {
    results.v[id] = vec4(results.v[id].xyz + radiance, 1.0);
  }
}

// The same sum in registers, for the megakernels: `sum` after bounce `bounce` added `radiance`, in the
// order and with the zero-skipping of pathAddRadiance, so the megakernels and the wavefront agree.
vec3 addBounceRadiance(vec3 sum, uint bounce, vec3 radiance) {
  if (bounce == 0u) return radiance;
  return radiance != vec3(0.0) ? sum + radiance : sum;
}

#ifdef RAYLAB_PATH_SHADING_GLSL
// ---- whole paths (generate, shade)
// p.radiance is this bounce's contribution only: it starts at zero.
PathVars loadPath(GpuPathState s, uint i, out uint id) {
  vec4 o = s.origin.v[i];
  uvec4 d = directionBits(s).v[i];
  vec4 t = s.throughput.v[i];
  PathVars p;
  p.origin = o.xyz;
  p.pdf = o.w;
  p.direction = uintBitsToFloat(d.xyz);
  p.throughput = t.xyz;
  p.radiance = vec3(0.0);
  id = d.w;
  p.alive = id != RL_DEAD_PATH;
  return p;
}

// A finished path only marks itself finished; a live one stores its next ray and the key stage's predicted
// length for it (-1: none yet; the shade that makes keys knows it).
void storePath(GpuPathState s, uint i, PathVars p, uint id, float predictedLength) {
  if (!p.alive) {
    markPathFinished(s, i);
    return;
  }
  s.origin.v[i] = vec4(p.origin, p.pdf);
  directionBits(s).v[i] = uvec4(floatBitsToUint(p.direction), id);
  s.throughput.v[i] = vec4(p.throughput, predictedLength);
}
void storePath(GpuPathState s, uint i, PathVars p, uint id) { storePath(s, i, p, id, -1.0); }

// ---- hits of the current bounce, in the order of the current state set
void storeHit(GpuHits h, uint i, HitRecord hit) {
  h.t.v[i] = hit.t;
  h.triangle.v[i] = hit.triangle;
  h.barycentric.v[i] = hit.bary;
  h.steps.v[i] = hit.steps;
}

// The hit for shading (no traversal steps: those are statistics only).
HitRecord loadHit(GpuHits h, uint i) {
  HitRecord hit;
  hit.t = h.t.v[i];
  hit.triangle = h.triangle.v[i];
  hit.bary = h.barycentric.v[i];
  hit.steps = 0u;
  return hit;
}
#endif  // RAYLAB_PATH_SHADING_GLSL

#endif
