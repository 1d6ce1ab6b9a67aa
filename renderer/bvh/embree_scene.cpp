#include "renderer/bvh/embree_scene.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace raylab {

EmbreeScene::EmbreeScene(const std::vector<Triangle>& triangles) {
  scene_ = rtcNewScene(device_.get());
  device_.check("rtcNewScene");
  try {
    rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
    if (!triangles.empty()) {
      RTCGeometry geometry = rtcNewGeometry(device_.get(), RTC_GEOMETRY_TYPE_TRIANGLE);
      device_.check("rtcNewGeometry");
      // Our triangles are unindexed: three vertices each, indices 3i, 3i+1, 3i+2, so Embree's primID is the
      // triangle's index.
      auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0,
                                                                  RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                                  3 * triangles.size()));
      auto* indices = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0,
                                                                    RTC_FORMAT_UINT3, 3 * sizeof(uint32_t),
                                                                    triangles.size()));
      if (!vertices || !indices) {
        rtcReleaseGeometry(geometry);
        device_.check("rtcSetNewGeometryBuffer");
        throw std::runtime_error("Embree: rtcSetNewGeometryBuffer gave no buffer");
      }
      for (size_t i = 0; i < triangles.size(); ++i)
        for (int k = 0; k < 3; ++k) {
          for (int c = 0; c < 3; ++c) vertices[9 * i + 3 * k + c] = triangles[i].v[k][c];
          indices[3 * i + k] = static_cast<uint32_t>(3 * i + k);
        }
      rtcCommitGeometry(geometry);
      rtcAttachGeometry(scene_, geometry);
      rtcReleaseGeometry(geometry);  // the scene holds it
    }
    rtcCommitScene(scene_);
    device_.check("rtcCommitScene");
  } catch (...) {
    rtcReleaseScene(scene_);
    throw;
  }
}

EmbreeScene::~EmbreeScene() {
  if (scene_) rtcReleaseScene(scene_);
}

namespace {

// Embree takes the closed segment [tnear, tfar]; our shaders' triangle test takes the open one (t > 0, t < tMax),
// so the bounds move in by one float each. Otherwise a ray that starts exactly on a triangle (a bounce ray from a
// point on the edge where two walls meet, offset along one wall's normal only, still lies in the other's plane)
// hits it at t = 0 in Embree and not on the GPU: 0.3% of the Cornell box's bounce rays disagreed that way.
RTCRay embreeRay(const glm::vec3& o, const glm::vec3& d, float tNear, float tMax) {
  RTCRay ray{};
  ray.org_x = o.x, ray.org_y = o.y, ray.org_z = o.z;
  ray.tnear = std::nextafter(tNear, std::numeric_limits<float>::infinity());
  ray.dir_x = d.x, ray.dir_y = d.y, ray.dir_z = d.z, ray.time = 0.0f;
  ray.tfar = std::nextafter(tMax, -std::numeric_limits<float>::infinity());
  ray.mask = 0xFFFFFFFFu;
  ray.id = 0;
  ray.flags = 0;
  return ray;
}

}  // namespace

EmbreeHit EmbreeScene::intersect(const glm::vec3& origin, const glm::vec3& direction, float tMax, float tNear) const {
  RTCRayHit rh{};
  rh.ray = embreeRay(origin, direction, tNear, tMax);
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  embree::intersect1(scene_, rh);
  EmbreeHit hit;
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return hit;
  hit.t = rh.ray.tfar;
  hit.triangle = rh.hit.primID;
  hit.bary = {rh.hit.u, rh.hit.v};
  hit.normal = {rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z};
  return hit;
}

bool EmbreeScene::occluded(const glm::vec3& origin, const glm::vec3& direction, float tMax, float tNear) const {
  RTCRay ray = embreeRay(origin, direction, tNear, tMax);
  embree::occluded1(scene_, ray);
  return ray.tfar < 0.0f;  // Embree sets tfar to -inf when something is in the way
}

}  // namespace raylab
