#include "app/tracebench/trace_rays.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "renderer/gpu_scene.h"
#include "renderer/reorder/key_functions.h"
#include "shaders/camera_order.h"

namespace raylab {
namespace {

constexpr float kUnbounded = 1e30f;  // the trace stage's tMax (trace.comp)
constexpr float kTwoPi = 6.28318530717959f;

// Any unit vector perpendicular to n, and n x it: a frame for directions about n.
void basisAround(const glm::vec3& n, glm::vec3& t, glm::vec3& b) {
  t = glm::normalize(std::abs(n.x) > 0.9f ? glm::cross(n, glm::vec3(0, 1, 0)) : glm::cross(n, glm::vec3(1, 0, 0)));
  b = glm::cross(n, t);
}

glm::vec3 aboutNormal(const glm::vec3& n, float x, float y, float z) {
  glm::vec3 t, b;
  basisAround(n, t, b);
  return glm::normalize(x * t + y * b + z * n);
}

}  // namespace

void RaySet::add(const glm::vec3& origin, const glm::vec3& direction, float tMax) {
  origins.emplace_back(origin, 0.0f);
  directions.emplace_back(direction, tMax);
}

glm::vec3 cameraRayDirection(const gpu::GpuCamera& cam, glm::vec2 ndc) {
  return glm::normalize(cam.forward + ndc.x * cam.tanHalfFovY * cam.aspect * cam.right + ndc.y * cam.tanHalfFovY * cam.up);
}

RaySet cameraRays(const gpu::GpuCamera& cam, uint32_t width, uint32_t height, CameraRayOrder order) {
  RaySet rays;
  const uint32_t n = width * height;
  rays.origins.reserve(n);
  rays.directions.reserve(n);
  for (uint32_t slot = 0; slot < n; ++slot) {
    const uint32_t pixel = order == CameraRayOrder::Tiles ? gpu::cameraPixelOfSlot(slot, width, height) : slot;
    const float x = (float(pixel % width) + 0.5f) / float(width);
    const float y = (float(pixel / width) + 0.5f) / float(height);
    rays.add(cam.position, cameraRayDirection(cam, glm::vec2(2.0f * x - 1.0f, 1.0f - 2.0f * y)), kUnbounded);
  }
  return rays;
}

std::vector<SurfacePoint> surfacePoints(const RaySet& rays, const std::vector<float>& t,
                                        const std::vector<uint32_t>& triangle, const std::vector<Triangle>& triangles) {
  std::vector<SurfacePoint> points;
  for (uint32_t i = 0; i < rays.size(); ++i) {
    if (!(t[i] > 0.0f) || triangle[i] >= triangles.size()) continue;
    const Triangle& tri = triangles[triangle[i]];
    const glm::vec3 dir(rays.directions[i]);
    glm::vec3 n = glm::cross(tri.v[1] - tri.v[0], tri.v[2] - tri.v[0]);
    if (!(glm::dot(n, n) > 0.0f)) continue;  // a degenerate triangle has no side to leave from
    n = glm::normalize(n);
    if (glm::dot(n, dir) > 0.0f) n = -n;
    points.push_back({glm::vec3(rays.origins[i]) + t[i] * dir, n});
  }
  return points;
}

glm::vec3 offsetOrigin(const glm::vec3& p, const glm::vec3& n, const glm::vec3& dir) {
  const float eps = 1e-4f * (1.0f + std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}));
  return p + (glm::dot(dir, n) >= 0.0f ? n : -n) * eps;
}

RaySet bounceRays(const std::vector<SurfacePoint>& points, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u01(0.0f, 1.0f);
  RaySet rays;
  for (const SurfacePoint& p : points) {
    const float r = std::sqrt(u01(rng)), phi = kTwoPi * u01(rng);
    const glm::vec3 d = aboutNormal(p.normal, r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0f, 1.0f - r * r)));
    rays.add(offsetOrigin(p.position, p.normal, d), d, kUnbounded);
  }
  return rays;
}

RaySet shadowRays(const std::vector<SurfacePoint>& points, const Scene& scene, float skyProbability, uint32_t seed) {
  // The renderer's emitter table over the scene's own order: each emitter with its power's cumulative share.
  std::vector<uint32_t> sceneOrder(scene.triangles.size());
  std::iota(sceneOrder.begin(), sceneOrder.end(), 0u);
  const std::vector<gpu::GpuEmitter> emitters = buildEmitterTable(scene, sceneOrder).emitters;
  if (emitters.empty() && !(skyProbability > 0.0f)) return {};  // no light at all: the shader traces no ray
  if (emitters.empty()) skyProbability = 1.0f;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u01(0.0f, 1.0f);
  RaySet rays;
  for (const SurfacePoint& p : points) {
    if (u01(rng) < skyProbability) {
      const float z = u01(rng), phi = kTwoPi * u01(rng), r = std::sqrt(std::max(0.0f, 1.0f - z * z));
      const glm::vec3 d = aboutNormal(p.normal, r * std::cos(phi), r * std::sin(phi), z);
      if (z > 0.0f) rays.add(offsetOrigin(p.position, p.normal, d), d, kUnbounded);
      continue;
    }
    const float pick = u01(rng);
    const auto e = std::lower_bound(emitters.begin(), emitters.end(), pick,  // as pickEmitter: cdf >= pick
                                    [](const gpu::GpuEmitter& x, float u) { return x.cdf < u; });
    const Triangle& light = scene.triangles[(e == emitters.end() ? emitters.back() : *e).triangle];
    float a = u01(rng), b = u01(rng);
    if (a + b > 1.0f) a = 1.0f - a, b = 1.0f - b;
    const glm::vec3 q = light.v[0] + a * (light.v[1] - light.v[0]) + b * (light.v[2] - light.v[0]);
    const glm::vec3 toLight = q - p.position;
    const float dist = glm::length(toLight);
    if (!(dist > 0.0f)) continue;
    const glm::vec3 d = toLight / dist;
    const glm::vec3 lightNormal = glm::cross(light.v[1] - light.v[0], light.v[2] - light.v[0]);
    const float cosLight = std::abs(glm::dot(glm::normalize(lightNormal), d));
    if (glm::dot(d, p.normal) <= 0.0f || !(cosLight > 1e-6f)) continue;  // no BSDF value or no light: no ray
    rays.add(offsetOrigin(p.position, p.normal, d), d, 0.999f * dist);
  }
  return rays;
}

std::string raySetBytes(const RaySet& rays) {
  std::string bytes;
  bytes.reserve(size_t(rays.size()) * 2 * sizeof(glm::vec4));
  for (uint32_t i = 0; i < rays.size(); ++i) {
    const glm::vec4 origin(glm::vec3(rays.origins[i]), 0.0f);
    bytes.append(reinterpret_cast<const char*>(&origin), sizeof origin);
    bytes.append(reinterpret_cast<const char*>(&rays.directions[i]), sizeof(glm::vec4));
  }
  return bytes;
}

std::string triangleBytes(const std::vector<Triangle>& triangles) {
  std::string bytes;
  bytes.reserve(triangles.size() * 3 * sizeof(glm::vec4));
  for (const Triangle& t : triangles)
    for (const glm::vec3& v : t.v) {
      const glm::vec4 p(v, 0.0f);
      bytes.append(reinterpret_cast<const char*>(&p), sizeof p);
    }
  return bytes;
}

RaySet sortedByKey(const RaySet& rays, KeyStrategy strategy, const gpu::GpuKeyParams& params,
                   const std::vector<float>& hitT, uint32_t ignoredBits) {
  std::vector<uint32_t> keys(rays.size()), order(rays.size());
  KeyEnv env;
  env.bounce = 1;
  for (uint32_t i = 0; i < rays.size(); ++i) {
    const KeyPath path{glm::vec3(rays.origins[i]), glm::vec3(rays.directions[i]), i, i < hitT.size() ? hitT[i] : -1.0f};
    float length = 0.0f;
    keys[i] = computeKey(strategyId(strategy), params, env, path, 1u, length) >> ignoredBits;
  }
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return keys[a] < keys[b]; });
  RaySet sorted;
  sorted.origins.reserve(rays.size());
  sorted.directions.reserve(rays.size());
  for (uint32_t i : order) {
    sorted.origins.push_back(rays.origins[i]);
    sorted.directions.push_back(rays.directions[i]);
  }
  return sorted;
}

}  // namespace raylab
