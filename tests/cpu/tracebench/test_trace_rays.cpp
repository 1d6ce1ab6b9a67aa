// The ray sets `raylab tracebench` traces (app/tracebench/trace_rays.h), checked on the CPU against what
// each kind of ray must be: camera rays one per pixel in the generate stage's slot order, bounce rays a
// cosine-weighted hemisphere, shadow rays ending just short of a point on an emitter or unbounded toward
// the sky above the surface.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <set>
#include <vector>

#include "app/tracebench/trace_rays.h"
#include "renderer/reorder/key_functions.h"
#include "renderer/reorder/key_grid.h"
#include "renderer/reorder/key_stage.h"
#include "shaders/camera_order.h"

namespace raylab {
namespace {

gpu::GpuCamera lookingDownZ(float aspect) {
  gpu::GpuCamera c{};
  c.position = glm::vec3(1.0f, 2.0f, 3.0f);
  c.forward = glm::vec3(0.0f, 0.0f, -1.0f);
  c.right = glm::vec3(1.0f, 0.0f, 0.0f);
  c.up = glm::vec3(0.0f, 1.0f, 0.0f);
  c.tanHalfFovY = 0.5f;
  c.aspect = aspect;
  return c;
}

TEST(TraceRays, CameraRaysAreOneAPixelInTheGenerateStagesOrder) {
  const uint32_t w = 37, h = 11;
  const gpu::GpuCamera cam = lookingDownZ(float(w) / float(h));
  const RaySet rays = cameraRays(cam, w, h);
  ASSERT_EQ(rays.size(), w * h);
  std::set<std::pair<int, int>> pixels;
  for (uint32_t slot = 0; slot < rays.size(); ++slot) {
    const glm::vec3 d(rays.directions[slot]);
    EXPECT_NEAR(glm::length(d), 1.0f, 1e-5f);
    EXPECT_EQ(glm::vec3(rays.origins[slot]), cam.position);
    EXPECT_EQ(rays.directions[slot].w, 1e30f);
    // Back from the direction to the pixel: x = (px + 0.5) / w, ndc = 2x - 1, on the plane z = -1.
    const glm::vec3 onPlane = d / -d.z;
    const float px = ((onPlane.x / (cam.tanHalfFovY * cam.aspect)) + 1.0f) * 0.5f * w - 0.5f;
    const float py = ((1.0f - onPlane.y / cam.tanHalfFovY)) * 0.5f * h - 0.5f;
    const uint32_t want = gpu::cameraPixelOfSlot(slot, w, h);
    EXPECT_NEAR(px, float(want % w), 1e-3f) << "slot " << slot;
    EXPECT_NEAR(py, float(want / w), 1e-3f) << "slot " << slot;
    pixels.insert({int(std::lround(px)), int(std::lround(py))});
  }
  EXPECT_EQ(pixels.size(), size_t(w) * h) << "a pixel was traced twice";
  // Scanline order: slot i is pixel i, the same rays.
  const RaySet rows = cameraRays(cam, w, h, CameraRayOrder::Scanline);
  for (uint32_t slot = 0; slot < rays.size(); ++slot)
    EXPECT_EQ(rows.directions[gpu::cameraPixelOfSlot(slot, w, h)], rays.directions[slot]) << "slot " << slot;
}

// A floor (z = 0, two triangles) under a camera looking straight down: every camera ray hits it.
struct Floor {
  std::vector<Triangle> triangles;
  Floor() {
    Triangle a, b;
    a.v[0] = {-10, -10, 0}, a.v[1] = {10, -10, 0}, a.v[2] = {10, 10, 0};
    b.v[0] = {-10, -10, 0}, b.v[1] = {10, 10, 0}, b.v[2] = {-10, 10, 0};
    triangles = {a, b};
  }
};

std::vector<SurfacePoint> floorPoints(uint32_t n) {
  RaySet down;
  std::vector<float> t;
  std::vector<uint32_t> tri;
  for (uint32_t i = 0; i < n; ++i) {
    const float x = -5.0f + 10.0f * float(i) / float(n);
    down.add({x, 0.3f, 4.0f}, {0.0f, 0.0f, -1.0f}, 1e30f);
    t.push_back(4.0f);
    tri.push_back(i % 2);
  }
  // Two misses, which make no points.
  down.add({0, 0, 4}, {0, 0, 1}, 1e30f);
  t.push_back(-1.0f);
  tri.push_back(0xFFFFFFFFu);
  return surfacePoints(down, t, tri, Floor().triangles);
}

TEST(TraceRays, SurfacePointsFaceTheRayAndSkipMisses) {
  const std::vector<SurfacePoint> points = floorPoints(100);
  ASSERT_EQ(points.size(), 100u);
  for (const SurfacePoint& p : points) {
    EXPECT_NEAR(p.position.z, 0.0f, 1e-6f);
    EXPECT_NEAR(p.normal.z, 1.0f, 1e-6f) << "the floor's normal must face the ray that came from above";
  }
}

TEST(TraceRays, BounceRaysFollowTheCosineLawAboveTheSurface) {
  const std::vector<SurfacePoint> points = floorPoints(20000);
  const RaySet rays = bounceRays(points, 7);
  ASSERT_EQ(rays.size(), points.size());
  double sumCos = 0.0, sumCos2 = 0.0;
  for (uint32_t i = 0; i < rays.size(); ++i) {
    const glm::vec3 d(rays.directions[i]);
    EXPECT_NEAR(glm::length(d), 1.0f, 1e-5f);
    ASSERT_GT(d.z, 0.0f) << "ray " << i << " leaves below the surface";
    EXPECT_GT(rays.origins[i].z, 0.0f) << "origin not lifted off the surface";
    sumCos += d.z;
    sumCos2 += d.z * d.z;
  }
  // Cosine-weighted: E[cos] = 2/3, E[cos^2] = 1/2 (uniform over the hemisphere would give 1/2 and 1/3).
  EXPECT_NEAR(sumCos / rays.size(), 2.0 / 3.0, 0.01);
  EXPECT_NEAR(sumCos2 / rays.size(), 0.5, 0.01);
  EXPECT_EQ(bounceRays(points, 7).directions, rays.directions) << "not deterministic for a seed";
}

TEST(TraceRays, ShadowRaysStopJustShortOfAPointOnTheLight) {
  Scene scene;
  scene.triangles = Floor().triangles;
  Material emitter;
  emitter.emissive = glm::vec3(5.0f);
  scene.materials = {Material{}, emitter};
  Triangle light;  // a small light 3 above the floor, facing down
  light.v[0] = {-1, -1, 3}, light.v[1] = {1, -1, 3}, light.v[2] = {0, 1, 3};
  light.material = 1;
  scene.triangles.push_back(light);
  const std::vector<SurfacePoint> points = floorPoints(500);
  const RaySet toLight = shadowRays(points, scene, 0.0f, 3);
  ASSERT_EQ(toLight.size(), points.size()) << "every floor point sees the light above it";
  for (uint32_t i = 0; i < toLight.size(); ++i) {
    const glm::vec3 o(toLight.origins[i]), d(toLight.directions[i]);
    const glm::vec3 end = o + toLight.directions[i].w / 0.999f * d;  // the sampled point, from about the origin
    EXPECT_NEAR(end.z, 3.0f, 1e-3f) << "ray " << i << " does not end on the light's plane";
    EXPECT_LE(std::abs(end.x), 1.0f + 1e-3f);
    EXPECT_GE(end.y, -1.0f - 1e-3f);
    EXPECT_LE(end.y, 1.0f + 1e-3f);
    EXPECT_LT(o.z + toLight.directions[i].w * d.z, 3.0f) << "the ray reaches the light itself";
  }
  // The sky: unbounded, above the surface, uniform over the hemisphere (E[cos] = 1/2).
  const RaySet toSky = shadowRays(floorPoints(20000), scene, 1.0f, 3);
  ASSERT_GT(toSky.size(), 19900u);
  double sumCos = 0.0;
  for (uint32_t i = 0; i < toSky.size(); ++i) {
    EXPECT_EQ(toSky.directions[i].w, 1e30f);
    ASSERT_GT(toSky.directions[i].z, 0.0f);
    sumCos += toSky.directions[i].z;
  }
  EXPECT_NEAR(sumCos / toSky.size(), 0.5, 0.01);
  // A light below the surface gives no BSDF value: no ray, as next-event estimation traces none.
  scene.triangles.back().v[0].z = scene.triangles.back().v[1].z = scene.triangles.back().v[2].z = -3.0f;
  EXPECT_EQ(shadowRays(points, scene, 0.0f, 3).size(), 0u);
  // No emitter: every shadow ray goes to the sky, if there is one; with neither, next-event estimation
  // traces nothing.
  scene.triangles.pop_back();
  const RaySet skyOnly = shadowRays(points, scene, 1.0f, 3);
  EXPECT_GT(skyOnly.size(), points.size() * 9 / 10);
  for (uint32_t i = 0; i < skyOnly.size(); ++i) EXPECT_EQ(skyOnly.directions[i].w, 1e30f);
  EXPECT_EQ(shadowRays(points, scene, 0.0f, 3).size(), 0u);
}

// Sorted as the path sorter sorts: the same rays, by a key that never falls along the order, and stably (rays
// of one key keep their order). Two-point keys on a grid over the floor's points, with all their bits and
// with the low bits --sort-bits 12 ignores (the sorter compares 23 + 1 bits: 12 ignored).
TEST(TraceRays, SortedByKeyIsAStablePermutationByTheStrategysKey) {
  const RaySet rays = bounceRays(floorPoints(5000), 11);
  Bounds box;
  box.min = glm::vec3(-10, -10, -1);
  box.max = glm::vec3(10, 10, 5);
  Settings s;
  KeyGrid grid = makeKeyGrid(box, glm::vec3(0, 0, 4), s);
  grid.gpu.spatialBits = spatialKeyBits(KeyStrategy::TwoPoint, grid.gpu);
  ASSERT_EQ(grid.gpu.spatialBits, RL_KEY_TWO_POINT_BITS) << "the grid is too coarse for this test";
  EXPECT_EQ(ignoredKeyBits(grid.gpu.spatialBits, 0), 0u);
  EXPECT_EQ(ignoredKeyBits(grid.gpu.spatialBits, 12), 12u);
  EXPECT_EQ(ignoredKeyBits(grid.gpu.spatialBits, 24), 0u);
  EXPECT_EQ(ignoredKeyBits(grid.gpu.spatialBits, 32), 0u);
  const gpu::GpuKeyParams params = baseKeyParams(grid, s);
  auto keyOf = [&](const RaySet& set, uint32_t i, uint32_t pathId) {
    float len = 0;
    const KeyPath path{glm::vec3(set.origins[i]), glm::vec3(set.directions[i]), pathId, -1.0f};
    return computeKey(strategyId(KeyStrategy::TwoPoint), params, KeyEnv{}, path, 1u, len);
  };
  uint32_t distinctAll = 0;
  for (const uint32_t sortBits : {0u, 12u}) {
    SCOPED_TRACE("sort bits " + std::to_string(sortBits));
    const uint32_t ignored = ignoredKeyBits(grid.gpu.spatialBits, sortBits);
    const RaySet sorted = sortedByKey(rays, KeyStrategy::TwoPoint, params, {}, ignored);
    ASSERT_EQ(sorted.size(), rays.size());
    // Where each sorted ray came from (the rays are distinct: random directions from distinct points).
    std::vector<uint32_t> from(sorted.size());
    std::set<uint32_t> seen;
    for (uint32_t i = 0; i < sorted.size(); ++i) {
      for (uint32_t j = 0; j < rays.size(); ++j)
        if (rays.origins[j] == sorted.origins[i] && rays.directions[j] == sorted.directions[i]) from[i] = j;
      seen.insert(from[i]);
    }
    EXPECT_EQ(seen.size(), rays.size()) << "not a permutation";
    uint32_t distinctKeys = 1;
    for (uint32_t i = 1; i < sorted.size(); ++i) {
      const uint32_t a = keyOf(rays, from[i - 1], from[i - 1]) >> ignored, b = keyOf(rays, from[i], from[i]) >> ignored;
      ASSERT_LE(a, b) << "keys fall at " << i;
      if (a == b) {
        EXPECT_LT(from[i - 1], from[i]) << "not stable at " << i;
      }
      distinctKeys += a != b;
    }
    EXPECT_GT(distinctKeys, 10u) << "the key orders nothing: the test proves nothing";
    if (sortBits == 0) distinctAll = distinctKeys;
    else EXPECT_LT(distinctKeys, distinctAll) << "ignoring 12 bits merged no keys";
  }
}

// --export's bytes: each ray's origin (w 0) and direction with tMax, each triangle's three vertices (w 0), as
// floats in order, so another tracer reads the very rays and triangles traced here.
TEST(TraceRays, ExportedBytesAreTheRaysAndTrianglesInOrder) {
  RaySet rays;
  rays.add(glm::vec3(1, 2, 3), glm::vec3(0, 0, 1), 1e30f);
  rays.add(glm::vec3(-4, 5.5f, 0.25f), glm::normalize(glm::vec3(1, 1, 0)), 7.5f);
  const std::string r = raySetBytes(rays);
  ASSERT_EQ(r.size(), 2u * 8u * sizeof(float));
  std::vector<float> f(16);
  std::memcpy(f.data(), r.data(), r.size());
  EXPECT_EQ(f, (std::vector<float>{1, 2, 3, 0, 0, 0, 1, 1e30f, -4, 5.5f, 0.25f, 0, rays.directions[1].x,
                                   rays.directions[1].y, 0, 7.5f}));
  std::vector<Triangle> tris(2);
  tris[0].v[0] = glm::vec3(1, 2, 3), tris[0].v[1] = glm::vec3(4, 5, 6), tris[0].v[2] = glm::vec3(7, 8, 9);
  tris[1].v[0] = glm::vec3(-1, -2, -3), tris[1].v[1] = glm::vec3(0.5f), tris[1].v[2] = glm::vec3(10, 0, -10);
  tris[1].material = 3;
  const std::string t = triangleBytes(tris);
  ASSERT_EQ(t.size(), 2u * 12u * sizeof(float));
  std::vector<float> g(24);
  std::memcpy(g.data(), t.data(), t.size());
  EXPECT_EQ(g, (std::vector<float>{1, 2, 3, 0, 4, 5, 6, 0, 7, 8, 9, 0, -1, -2, -3, 0, 0.5f, 0.5f, 0.5f, 0, 10, 0, -10, 0}));
  EXPECT_TRUE(raySetBytes(RaySet{}).empty());
}

}  // namespace
}  // namespace raylab
