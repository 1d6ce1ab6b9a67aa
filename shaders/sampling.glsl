// Direction sampling helpers.
#ifndef RAYLAB_SAMPLING_GLSL
#define RAYLAB_SAMPLING_GLSL

const float kPi = 3.14159265358979;

// Orthonormal basis around n (Duff et al. 2017), no branch on the sign beyond copysign.
void basisAround(vec3 n, out vec3 t, out vec3 b) {
  float s = n.z >= 0.0 ? 1.0 : -1.0;
  float a = -1.0 / (s + n.z);
  float c = n.x * n.y * a;
  t = vec3(1.0 + s * n.x * n.x * a, s * c, -s * n.x);
  b = vec3(c, s + n.y * n.y * a, -n.y);
}

vec3 toWorld(vec3 local, vec3 n) {
  vec3 t, b;
  basisAround(n, t, b);
  return local.x * t + local.y * b + local.z * n;
}

vec3 sampleCosineHemisphere(vec2 u) {
  float r = sqrt(u.x);
  float phi = 2.0 * kPi * u.y;
  return vec3(r * cos(phi), r * sin(phi), sqrt(max(0.0, 1.0 - u.x)));
}

vec3 sampleUniformSphere(vec2 u) {
  float z = 1.0 - 2.0 * u.x;
  float r = sqrt(max(0.0, 1.0 - z * z));
  float phi = 2.0 * kPi * u.y;
  return vec3(r * cos(phi), r * sin(phi), z);
}

// Uniform point on a triangle as barycentrics (square-root parametrisation).
vec2 sampleTriangle(vec2 u) {
  float su = sqrt(u.x);
  return vec2(1.0 - su, u.y * su);
}

float powerHeuristic(float a, float b) {
  float a2 = a * a, b2 = b * b;
  return a2 + b2 > 0.0 ? a2 / (a2 + b2) : 0.0;
}

float luminance(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }

#endif
