// The one place that knows which Embree is installed: Embree 3 on Debian 12 (libembree-dev 3.13), Embree 4
// on Debian 13 (4.3). Everything else includes this header and calls the wrappers below for what differs
// between them; the builder API (rtcBuildBVH, RTCBuildArguments and its callbacks) is the same in both.
#pragma once

#if __has_include(<embree4/rtcore.h>)
#include <embree4/rtcore.h>
#define RAYLAB_EMBREE_MAJOR 4
#elif __has_include(<embree3/rtcore.h>)
#include <embree3/rtcore.h>
#define RAYLAB_EMBREE_MAJOR 3
#else
#error "Embree 3 or 4 is required (Debian: libembree-dev)"
#endif

namespace raylab::embree {

// Embree 3 passes an RTCIntersectContext to every query; Embree 4 dropped it (optional arguments instead).
inline void intersect1(RTCScene scene, RTCRayHit& rayHit) {
#if RAYLAB_EMBREE_MAJOR >= 4
  rtcIntersect1(scene, &rayHit);
#else
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcIntersect1(scene, &context, &rayHit);
#endif
}

inline void occluded1(RTCScene scene, RTCRay& ray) {
#if RAYLAB_EMBREE_MAJOR >= 4
  rtcOccluded1(scene, &ray);
#else
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcOccluded1(scene, &context, &ray);
#endif
}

}  // namespace raylab::embree
