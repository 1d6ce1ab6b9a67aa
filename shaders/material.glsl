// The surface model: Lambert diffuse plus a GGX microfacet lobe (Smith shadowing, Schlick Fresnel),
// parametrised like glTF's metallic-roughness. specularWeight 0 leaves pure Lambert (the white furnace).
#ifndef RAYLAB_MATERIAL_GLSL
#define RAYLAB_MATERIAL_GLSL

#include "sampling.glsl"

struct SurfaceParams {
  vec3 diffuse;   // albedo of the Lambert lobe
  vec3 f0;        // specular reflectance at normal incidence
  float alpha;    // GGX roughness (squared perceptual roughness)
  float specularProbability;
};

SurfaceParams surfaceParams(GpuMaterial m, vec3 baseColor) {
  SurfaceParams s;
  s.diffuse = baseColor * (1.0 - m.metallic);
  s.f0 = mix(vec3(0.04), baseColor, m.metallic) * m.specularWeight;
  s.alpha = max(m.roughness * m.roughness, 2e-3);
  s.specularProbability = m.specularWeight > 0.0 ? mix(0.2, 1.0, m.metallic) : 0.0;
  return s;
}

float ggxD(float nh, float a) {
  float a2 = a * a;
  float d = nh * nh * (a2 - 1.0) + 1.0;
  return a2 / (kPi * d * d);
}

float smithG1(float nv, float a) {
  float a2 = a * a;
  return 2.0 * nv / (nv + sqrt(a2 + (1.0 - a2) * nv * nv));
}

vec3 schlick(vec3 f0, float vh) { return f0 + (1.0 - f0) * pow(1.0 - vh, 5.0); }

// BSDF value times cos(wi, n), and the solid-angle pdf of sampling wi, for outgoing wo (both unit, away
// from the surface; n faces wo).
vec3 evalSurface(SurfaceParams s, vec3 n, vec3 wo, vec3 wi, out float pdf) {
  pdf = 0.0;
  float ni = dot(n, wi), no = dot(n, wo);
  if (ni <= 0.0 || no <= 0.0) return vec3(0.0);
  vec3 f = s.diffuse / kPi;
  pdf = (1.0 - s.specularProbability) * ni / kPi;
  if (s.specularProbability > 0.0) {
    vec3 h = normalize(wi + wo);
    float nh = max(dot(n, h), 0.0), vh = max(dot(wo, h), 1e-6);
    float d = ggxD(nh, s.alpha);
    f += d * smithG1(ni, s.alpha) * smithG1(no, s.alpha) * schlick(s.f0, vh) / (4.0 * ni * no);
    pdf += s.specularProbability * d * nh / (4.0 * vh);
  }
  return f * ni;
}

// Samples wi; returns false when the sample is below the surface.
bool sampleSurface(SurfaceParams s, vec3 n, vec3 wo, vec3 u, out vec3 wi) {
  if (u.z < s.specularProbability) {
    // GGX normal distribution sampling of the half vector.
    float phi = 2.0 * kPi * u.x;
    float cosTheta = sqrt((1.0 - u.y) / (1.0 + (s.alpha * s.alpha - 1.0) * u.y));
    float sinTheta = sqrt(max(0.0, 1.0 - cosTheta * cosTheta));
    vec3 h = toWorld(vec3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta), n);
    wi = reflect(-wo, h);
  } else {
    wi = toWorld(sampleCosineHemisphere(u.xy), n);
  }
  return dot(wi, n) > 0.0;
}

#endif
