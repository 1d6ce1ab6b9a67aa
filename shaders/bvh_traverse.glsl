// Closest-hit and any-hit BVH traversal shared by the trace stage, the megakernel, shadow rays and the
// oracle key: the binary tree here, the wide one in bvh_traverse_wide.glsl, chosen by GpuScene::bvhLayout.
// Stack-based, nearer child first. `steps` counts loop iterations, one node visited each (a binary node here;
// a wide node or a leaf in the wide traversal): the per-path work whose spread within a warp is what ray
// reordering tries to shrink.
#ifndef RAYLAB_BVH_TRAVERSE_GLSL
#define RAYLAB_BVH_TRAVERSE_GLSL

// A stage may define RL_TRAVERSAL_STEP() before including this file to observe every loop iteration
// (the trace stage's SIMT counting); by default it does nothing.
#ifndef RL_TRAVERSAL_STEP
#define RL_TRAVERSAL_STEP()
#endif

struct HitRecord {
  float t;        // negative: no hit
  uint triangle;  // BVH-order triangle index
  vec2 bary;
  uint steps;
};

// Slab test; returns the entry distance or a huge value when the box is missed or beyond tMax.
float intersectBox(vec3 bmin, vec3 bmax, vec3 origin, vec3 invDir, float tMax) {
  vec3 t0 = (bmin - origin) * invDir;
  vec3 t1 = (bmax - origin) * invDir;
  vec3 tn = min(t0, t1);
  vec3 tf = max(t0, t1);
  float enter = max(max(tn.x, tn.y), max(tn.z, 0.0));
  float leave = min(min(tf.x, tf.y), min(tf.z, tMax));
  return enter <= leave ? enter : 1e30;
}

// Moeller-Trumbore on a triangle's first vertex and two edges; updates hit when nearer.
void intersectTriangleEdges(vec3 v0, vec3 e1, vec3 e2, uint index, vec3 origin, vec3 dir, inout HitRecord hit,
                            inout float tMax) {
  vec3 p = cross(dir, e2);
  float det = dot(e1, p);
  if (abs(det) < 1e-12) return;
  float inv = 1.0 / det;
  vec3 s = origin - v0;
  float u = dot(s, p) * inv;
  if (u < 0.0 || u > 1.0) return;
  vec3 q = cross(s, e1);
  float v = dot(dir, q) * inv;
  if (v < 0.0 || u + v > 1.0) return;
  float t = dot(e2, q) * inv;
  if (t > 0.0 && t < tMax) {
    tMax = t;
    hit.t = t;
    hit.triangle = index;
    hit.bary = vec2(u, v);
  }
}

void intersectTriangle(GpuTriangle tri, uint index, vec3 origin, vec3 dir, inout HitRecord hit, inout float tMax) {
  intersectTriangleEdges(tri.v0, tri.e1, tri.e2, index, origin, dir, hit, tMax);
}

// What a traversal starts from (both layouts): no hit yet, no step taken.
HitRecord noHit() {
  HitRecord hit;
  hit.t = -1.0;
  hit.triangle = 0u;
  hit.bary = vec2(0.0);
  hit.steps = 0u;
  return hit;
}

// Avoid division by zero in the slab test while keeping the sign of each direction component.
vec3 safeInverse(vec3 d) {
  const float eps = 1e-20;
  return 1.0 / vec3(abs(d.x) > eps ? d.x : (d.x >= 0.0 ? eps : -eps),
                    abs(d.y) > eps ? d.y : (d.y >= 0.0 ? eps : -eps),
                    abs(d.z) > eps ? d.z : (d.z >= 0.0 ? eps : -eps));
}

// anyHit: stop at the first hit (shadow rays).
HitRecord traverseBvh(GpuScene scene, vec3 origin, vec3 dir, float tMax, bool anyHit) {
  HitRecord hit = noHit();
  vec3 invDir = safeInverse(dir);
  uint stack[RL_BVH_STACK];
  uint sp = 0u;
  uint node = 0u;
  if (intersectBox(scene.nodes.v[0].boundsMin, scene.nodes.v[0].boundsMax, origin, invDir, tMax) >= 1e30)
    return hit;
  while (true) {
    hit.steps++;
    RL_TRAVERSAL_STEP();
    BvhNode n = scene.nodes.v[node];
    if (n.triCount > 0u) {
      for (uint i = 0u; i < n.triCount; ++i) {
        uint index = n.leftOrFirst + i;
        intersectTriangle(scene.triangles.v[index], index, origin, dir, hit, tMax);
      }
      if (anyHit && hit.t > 0.0) return hit;
      if (sp == 0u) break;
      node = stack[--sp];
      continue;
    }
    uint left = n.leftOrFirst;
    uint right = left + 1u;
    BvhNode ln = scene.nodes.v[left];
    BvhNode rn = scene.nodes.v[right];
    float dl = intersectBox(ln.boundsMin, ln.boundsMax, origin, invDir, tMax);
    float dr = intersectBox(rn.boundsMin, rn.boundsMax, origin, invDir, tMax);
    if (dl > dr) {
      float td = dl; dl = dr; dr = td;
      uint tn = left; left = right; right = tn;
    }
    if (dl >= 1e30) {
      if (sp == 0u) break;
      node = stack[--sp];
      continue;
    }
    node = left;
    if (dr < 1e30 && sp < RL_BVH_STACK) stack[sp++] = right;
  }
  return hit;
}

#include "bvh_traverse_wide.glsl"

// The layout is GpuScene::bvhLayout (Settings::bvh), the same for every invocation of a dispatch: a uniform
// branch, no divergence.
HitRecord traverseSceneBvh(GpuScene scene, vec3 origin, vec3 dir, float tMax, bool anyHit) {
  if (scene.bvhLayout == RL_BVH_WIDE) return traverseBvhWide(scene, origin, dir, tMax, anyHit);
  return traverseBvh(scene, origin, dir, tMax, anyHit);
}

HitRecord traceClosest(GpuScene scene, vec3 origin, vec3 dir, float tMax) {
  return traverseSceneBvh(scene, origin, dir, tMax, false);
}

bool occluded(GpuScene scene, vec3 origin, vec3 dir, float tMax) {
  return traverseSceneBvh(scene, origin, dir, tMax, true).t > 0.0;
}

#endif
