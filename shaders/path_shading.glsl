// One path vertex of the integrator, shared by the wavefront shade stage and the megakernel so both run
// the same estimator: emission (MIS-weighted against light sampling), next-event estimation toward an
// emissive triangle or the sky (MIS-weighted against BSDF sampling), then a BSDF sample for the next ray.
// Bounce b traces ray b; the vertex of the last bounce adds emission only.
#ifndef RAYLAB_PATH_SHADING_GLSL
#define RAYLAB_PATH_SHADING_GLSL

#include "bvh_traverse.glsl"
#include "material.glsl"
#include "rng.glsl"

// The visibility test of next-event estimation: our BVH's any-hit traversal, unless a ray-tracing stage
// defined RL_OCCLUDED as its traceRayEXT test (rt_stage.glsl) before including this file.
#ifndef RL_OCCLUDED
#define RL_OCCLUDED occluded
#endif

struct PathVars {
  vec3 origin;
  float pdf;  // solid-angle pdf of the BSDF sample that made this ray; 0 for camera rays (no MIS)
  vec3 direction;
  vec3 throughput;
  vec3 radiance;  // gathered at this vertex (shadePath adds to it; callers start each bounce at zero)
  bool alive;
};

PathVars cameraPath(GpuCamera cam, uint pixel, uint width, uint height, inout uint rng) {
  float x = (float(pixel % width) + rngNext(rng)) / float(width);
  float y = (float(pixel / width) + rngNext(rng)) / float(height);
  vec2 ndc = vec2(2.0 * x - 1.0, 1.0 - 2.0 * y);
  PathVars p;
  p.origin = cam.position;
  p.pdf = 0.0;
  p.direction = normalize(cam.forward + ndc.x * cam.tanHalfFovY * cam.aspect * cam.right +
                          ndc.y * cam.tanHalfFovY * cam.up);
  p.throughput = vec3(1.0);
  p.radiance = vec3(0.0);
  p.alive = true;
  return p;
}

vec3 srgbToLinear(vec3 c) {
  return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), greaterThan(c, vec3(0.04045)));
}

// Nearest-texel lookup with wrapping; texels are sRGB-encoded RGBA8.
vec3 sampleBaseColorTexture(GpuScene scene, int texture, vec2 uv) {
  GpuTextureInfo info = scene.textureInfos.v[texture];
  vec2 w = uv - floor(uv);
  uint x = min(uint(w.x * float(info.width)), info.width - 1u);
  uint y = min(uint(w.y * float(info.height)), info.height - 1u);
  uint t = scene.texels.v[info.offset + y * info.width + x];
  return srgbToLinear(vec3(t & 255u, (t >> 8) & 255u, (t >> 16) & 255u) / 255.0);
}

vec3 baseColorAt(GpuScene scene, GpuMaterial m, GpuTriangle tri, vec2 bary) {
  vec3 c = m.baseColor;
  if (m.baseColorTexture >= 0 && scene.hasUvs != 0u) {
    GpuTriangleUv t = scene.uvs.v[tri.sourceIndex];
    vec2 uv = (1.0 - bary.x - bary.y) * t.uv0 + bary.x * t.uv1 + bary.y * t.uv2;
    c *= sampleBaseColorTexture(scene, m.baseColorTexture, uv);
  }
  return c;
}

// Offset along the normal, scaled with the magnitude of the position so large scenes do not self-intersect.
vec3 offsetOrigin(vec3 p, vec3 n, vec3 dir) {
  float eps = 1e-4 * (1.0 + max(max(abs(p.x), abs(p.y)), abs(p.z)));
  return p + (dot(dir, n) >= 0.0 ? n : -n) * eps;
}

uint pickEmitter(GpuScene scene, float u) {
  uint lo = 0u, hi = scene.emitterCount - 1u;
  while (lo < hi) {
    uint mid = (lo + hi) / 2u;
    if (scene.emitters.v[mid].cdf < u) lo = mid + 1u; else hi = mid;
  }
  return scene.emitters.v[lo].triangle;
}

// Light sampling from `pos`: a point on an emissive triangle or a sky direction. Returns the MIS-weighted
// contribution (before throughput).
vec3 nextEventEstimate(GpuScene scene, vec3 pos, vec3 n, vec3 wo, SurfaceParams s, inout uint rng) {
  float pickSky = rngNext(rng);
  vec2 u = vec2(rngNext(rng), rngNext(rng));
  float uEmitter = rngNext(rng);
  vec3 wi;
  float lightPdf, dist;
  vec3 le;
  if (pickSky < scene.skyLightProbability) {
    wi = sampleUniformSphere(u);
    lightPdf = scene.skyLightProbability / (4.0 * kPi);
    dist = 1e30;
    le = scene.skyColor;
  } else {
    if (scene.emitterCount == 0u) return vec3(0.0);
    GpuTriangle tri = scene.triangles.v[pickEmitter(scene, uEmitter)];
    vec2 b = sampleTriangle(u);
    vec3 q = tri.v0 + b.x * tri.e1 + b.y * tri.e2;
    vec3 d = q - pos;
    float d2 = dot(d, d);
    if (d2 <= 0.0) return vec3(0.0);
    dist = sqrt(d2);
    wi = d / dist;
    vec3 ln = normalize(cross(tri.e1, tri.e2));
    float cosLight = abs(dot(ln, wi));
    if (cosLight <= 1e-6) return vec3(0.0);
    GpuMaterial lm = scene.materials.v[tri.materialId];
    lightPdf = (1.0 - scene.skyLightProbability) * lm.emitterPdfScale * d2 / cosLight;
    le = lm.emissive;
    dist *= 0.999;  // stop short of the light itself
  }
  float bsdfPdf;
  vec3 fcos = evalSurface(s, n, wo, wi, bsdfPdf);
  if (bsdfPdf <= 0.0 || lightPdf <= 0.0) return vec3(0.0);
  if (RL_OCCLUDED(scene, offsetOrigin(pos, n, wi), wi, dist)) return vec3(0.0);
  return fcos * le * powerHeuristic(lightPdf, bsdfPdf) / lightPdf;
}

// Shades the result of tracing path p's ray at bounce `bounce` of `bounceCount`.
void shadePath(GpuScene scene, inout PathVars p, HitRecord hit, uint bounce, uint bounceCount, inout uint rng) {
  if (hit.t < 0.0) {
    float w = p.pdf > 0.0 ? powerHeuristic(p.pdf, scene.skyLightProbability / (4.0 * kPi)) : 1.0;
    p.radiance += p.throughput * scene.skyColor * w;
    p.alive = false;
    return;
  }
  GpuTriangle tri = scene.triangles.v[hit.triangle];
  GpuMaterial m = scene.materials.v[tri.materialId];
  vec3 pos = p.origin + hit.t * p.direction;
  vec3 n = normalize(cross(tri.e1, tri.e2));
  if (dot(n, p.direction) > 0.0) n = -n;  // two-sided surfaces
  vec3 wo = -p.direction;

  if (m.emissive != vec3(0.0)) {
    float w = 1.0;
    if (p.pdf > 0.0) {
      float cosLight = max(dot(n, wo), 1e-6);
      float lightPdf = (1.0 - scene.skyLightProbability) * m.emitterPdfScale * hit.t * hit.t / cosLight;
      w = powerHeuristic(p.pdf, lightPdf);
    }
    p.radiance += p.throughput * m.emissive * w;
  }
  if (bounce + 1u >= bounceCount) {
    p.alive = false;
    return;
  }
  SurfaceParams s = surfaceParams(m, baseColorAt(scene, m, tri, hit.bary));
  p.radiance += p.throughput * nextEventEstimate(scene, pos, n, wo, s, rng);

  vec3 wi;
  vec3 u = vec3(rngNext(rng), rngNext(rng), rngNext(rng));
  float pdf = 0.0;
  bool above = sampleSurface(s, n, wo, u, wi);
  vec3 fcos = above ? evalSurface(s, n, wo, wi, pdf) : vec3(0.0);
  if (!above || pdf <= 0.0 || fcos == vec3(0.0)) {
    p.alive = false;
    return;
  }
  p.throughput *= fcos / pdf;
  p.origin = offsetOrigin(pos, n, wi);
  p.direction = wi;
  p.pdf = pdf;
}

// Radiance that reaches the accumulator: non-finite values (a numerical accident) become black rather
// than poisoning the pixel forever.
vec4 finishedRadiance(vec3 radiance) {
  bool finite = !any(isnan(radiance)) && !any(isinf(radiance));
  return vec4(finite ? radiance : vec3(0.0), 1.0);
}

#endif
