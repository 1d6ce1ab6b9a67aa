// The ray sets `raylab tracebench` traces, made on the CPU so that every kind of ray is traced alone by the
// same traversal the renderer calls (hit_query.comp): camera rays, one diffuse bounce from their hits, and
// next-event estimation's shadow rays from the same hits. Deterministic for a seed, so runs compare.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/scene.h"
#include "renderer/settings/settings.h"
#include "shaders/key_types.h"
#include "shaders/shared_types.h"

namespace raylab {

// Rays as hit_query.comp reads them: origin xyz (w unused), direction xyz (unit) with tMax in w.
struct RaySet {
  std::vector<glm::vec4> origins;
  std::vector<glm::vec4> directions;
  void add(const glm::vec3& origin, const glm::vec3& direction, float tMax);
  uint32_t size() const { return static_cast<uint32_t>(origins.size()); }
};

// One ray through each pixel's centre, in the slots the generate stage gives camera paths (Tiles:
// camera_order.h's 8x4-pixel tiles, the order the wavefront's first trace meets) or row by row (Scanline).
enum class CameraRayOrder { Tiles, Scanline };
// path_shading.glsl's cameraPath direction through the image point `ndc` (-1..1 on each axis, +y up).
glm::vec3 cameraRayDirection(const gpu::GpuCamera& camera, glm::vec2 ndc);
RaySet cameraRays(const gpu::GpuCamera& camera, uint32_t width, uint32_t height,
                  CameraRayOrder order = CameraRayOrder::Tiles);

// Where a ray of `rays` hit: the point and the geometric normal turned toward the ray (surfaces are
// two-sided, as in path_shading.glsl). `t` < 0 is a miss; `triangle` is the scene's triangle index.
struct SurfacePoint {
  glm::vec3 position;
  glm::vec3 normal;
};
std::vector<SurfacePoint> surfacePoints(const RaySet& rays, const std::vector<float>& t,
                                        const std::vector<uint32_t>& triangle, const std::vector<Triangle>& triangles);

// path_shading.glsl's offsetOrigin: a new ray's origin lifted off the surface, to the side it leaves toward.
glm::vec3 offsetOrigin(const glm::vec3& p, const glm::vec3& n, const glm::vec3& dir);

// One cosine-weighted direction about each point's normal (a diffuse bounce), unbounded.
RaySet bounceRays(const std::vector<SurfacePoint>& points, uint32_t seed);

// One shadow ray a point, as next-event estimation traces it: with `skyProbability` toward the sky (a
// uniform direction above the surface, unbounded; below it the shader never traces), otherwise toward a
// uniform point of an emissive triangle picked by its power (the renderer's emitter table), stopping at
// 0.999 of the distance. Points whose light lies behind their surface or in their plane get no ray, as in
// the shader; a scene with neither emitters nor sky (`skyProbability` 0) gets none at all.
RaySet shadowRays(const std::vector<SurfacePoint>& points, const Scene& scene, float skyProbability, uint32_t seed);

// `rays` in the order the path sorter would give them: each ray keyed by `strategy`'s key function (the CPU
// twins of keys.glsl, with `params`; ray i is path i, and `hitT[i]` its true hit distance, which only the
// oracle reads: may be empty otherwise), then stably sorted by key, as the radix sort orders them. For the
// strategies that learn nothing (learned lengths need frames of traces, which a batch of rays has not had).
// The sort compares keys without their `ignoredBits` low bits, as the radix sort does for --sort-bits
// (ignoredKeyBits).
RaySet sortedByKey(const RaySet& rays, KeyStrategy strategy, const gpu::GpuKeyParams& params,
                   const std::vector<float>& hitT, uint32_t ignoredBits = 0);

// The files of `tracebench --export`, so that another tracer (a public kernel, a CPU traversal) traces the very
// rays and triangles timed here. Little-endian 32-bit floats, no header:
// - rays: per ray 8 floats, origin x y z and 0, then the unit direction x y z and tMax (1e30: unbounded);
// - triangles: per triangle 12 floats, the vertices v0 v1 v2 each as x y z and 0, in the scene's triangle order
//   (the index hits report and Embree checks).
std::string raySetBytes(const RaySet& rays);
std::string triangleBytes(const std::vector<Triangle>& triangles);

}  // namespace raylab
