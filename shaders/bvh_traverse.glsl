// Closest-hit and any-hit BVH traversal shared by the trace stage, the megakernel, shadow rays and the
// oracle key: the binary tree here, the wide one in bvh_traverse_wide.glsl, chosen by GpuScene::bvhLayout.
// Stack-based, nearer child first. `steps` counts loop iterations, one node visited each (a pair node here:
// both children of a binary node; a wide node or a leaf in the wide traversal): the per-path work whose spread within a warp is what ray
// reordering tries to shrink.
#ifndef RAYLAB_BVH_TRAVERSE_GLSL
#define RAYLAB_BVH_TRAVERSE_GLSL

#include "spec_ids.h"

// A stage may define RL_TRAVERSAL_STEP() before including this file to observe every loop iteration
// (the trace stage's SIMT counting); by default it does nothing.
#ifndef RL_TRAVERSAL_STEP
#define RL_TRAVERSAL_STEP()
#endif

// Counting steps costs the trace 1-3.7% of its rays per second on the H200 (docs/results/h200-trace-tuning), so
// the trace and the megakernel count them only on frames that read them (the warp statistics of detailed
// frames, a heatmap): the host sets this to false elsewhere. `steps` is then 0.
layout(constant_id = RL_SPEC_COUNTS_STEPS) const bool kCountsSteps = true;

struct HitRecord {
  float t;        // negative: no hit
  uint triangle;  // BVH-order triangle index
  vec2 bary;
  uint steps;
};

// Moeller-Trumbore on a triangle's first vertex and two edges; updates hit when nearer. Without early exits:
// u, v and t are all computed, then one test, which a lane of a diverged warp passes through once. A ray
// parallel to the plane (det 0) divides by zero; the NaNs or infinities that follow fail the test. Against
// exits after det, u and v, the Sponza trace on the H200 gained 2% on camera and bounce rays with the megakernel
// 2.3% shorter (docs/results/h200-lean-steps). Testing u, v and t against |det| before dividing (only a hit
// divides) did not pay: 0.5-2% slower rays, 1.0-1.3% longer frames (docs/results/h200-trace-tuning).
void intersectTriangleEdges(vec3 v0, vec3 e1, vec3 e2, uint index, vec3 origin, vec3 dir, inout HitRecord hit,
                            inout float tMax) {
  const vec3 p = cross(dir, e2);
  const float inv = 1.0 / dot(e1, p);
  const vec3 s = origin - v0;
  const float u = dot(s, p) * inv;
  const vec3 q = cross(s, e1);
  const float v = dot(dir, q) * inv;
  const float t = dot(e2, q) * inv;
  if (u >= 0.0 && v >= 0.0 && u + v <= 1.0 && t > 0.0 && t < tMax) {
    tMax = t;
    hit.t = t;
    hit.triangle = index;
    hit.bary = vec2(u, v);
  }
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

// Which of a pair node's two child boxes the ray enters before tMax (x: child 0, y: child 1), and their entry
// distances. The slabs as bounds * invDir - origin * invDir: one multiply-add a plane. Returning the test
// itself, rather than a distance set to 1e30 on a miss for the loop to compare again, gave the H200's trace 3.5-7.6%
// more camera rays a second and the megakernel a 2.7% shorter frame (docs/results/h200-lean-steps).
bvec2 enterPair(vec4 bx, vec4 by, vec4 bz, vec3 invDir, vec3 originInv, float tMax, out vec2 enter) {
  const vec4 tx = bx * invDir.x - originInv.x;
  const vec4 ty = by * invDir.y - originInv.y;
  const vec4 tz = bz * invDir.z - originInv.z;
  enter = max(max(min(tx.xz, tx.yw), min(ty.xz, ty.yw)), max(min(tz.xz, tz.yw), vec2(0.0)));
  const vec2 leave = min(min(max(tx.xz, tx.yw), max(ty.xz, ty.yw)), min(max(tz.xz, tz.yw), vec2(tMax)));
  return lessThanEqual(enter, leave);
}

// The leaf entries first .. first + count - 1 (GpuLeafTriangle: v0 with the BVH-order index in w, two edges); a
// hit reports the entry's triangle. True when anyHit may stop.
bool intersectLeaf(TriangleQuads entries, uint first, uint count, vec3 origin, vec3 dir, inout HitRecord hit,
                   inout float tMax, bool anyHit) {
  for (uint entry = first; entry < first + count; ++entry) {
    const vec4 v0 = entries.v[3u * entry];
    intersectTriangleEdges(v0.xyz, entries.v[3u * entry + 1u].xyz, entries.v[3u * entry + 2u].xyz,
                           floatBitsToUint(v0.w), origin, dir, hit, tMax);
  }
  return anyHit && hit.t > 0.0;
}

// A child travels through the traversal (the next node, the stack) as the word its parent stores: a leaf's
// RL_LEAF_WORD, an interior child's pair-node index below RL_LEAF_TAG.
bool isLeafWord(uint word) { return word >= RL_LEAF_TAG; }

// One leaf (its word) against the ray; true when anyHit may stop.
bool intersectLeafWord(TriangleQuads tris, uint word, vec3 origin, vec3 dir, inout HitRecord hit, inout float tMax,
                       bool anyHit) {
  return intersectLeaf(tris, RL_LEAF_FIRST(word), RL_LEAF_COUNT(word), origin, dir, hit, tMax, anyHit);
}

// A binary tree as pair nodes (BvhPairNode), with or without spatial splits (GpuScene::nodes and leafTriangles
// are the chosen tree's). Each iteration either tests a pair node's two boxes (one fetch of four 16-byte words)
// or intersects one leaf: a leaf is visited like a node, so every lane runs the one triangle loop at one place
// in the code. Interior and leaf children alike are visited nearer first, the farther pushed.
// anyHit: stop at the first hit (shadow rays). `steps` counts the iterations: pair nodes and leaves visited.
HitRecord traverseBvh(GpuScene scene, vec3 origin, vec3 dir, float tMax, bool anyHit) {
  HitRecord hit = noHit();
  const vec3 invDir = safeInverse(dir);
  const vec3 originInv = origin * invDir;
  BvhPairQuads nodes = BvhPairQuads(scene.nodes);
  TriangleQuads tris = TriangleQuads(scene.leafTriangles);
  uint stack[RL_BVH_STACK];
  uint sp = 0u;
  uint node = 0u;
  while (true) {
    if (kCountsSteps) hit.steps++;
    RL_TRAVERSAL_STEP();
    if (isLeafWord(node)) {
      if (intersectLeafWord(tris, node, origin, dir, hit, tMax, anyHit)) return hit;
      if (sp == 0u) break;
      node = stack[--sp];
      continue;
    }
    const uvec4 children = floatBitsToUint(nodes.v[4u * node + 3u]);
    vec2 d;
    const bvec2 entered = enterPair(nodes.v[4u * node], nodes.v[4u * node + 1u], nodes.v[4u * node + 2u], invDir,
                                    originInv, tMax, d);
    // The children's words as stored (BvhPairNode::child): a missing child's box is never entered.
    const bool hit0 = entered.x;
    const bool hit1 = entered.y;
    const uint child0 = children.x;
    const uint child1 = children.y;
    if (hit0 && hit1) {
      const bool firstNearer = d.x <= d.y;
      // The bound check stays although the host keeps every tree within RL_BVH_STACK. Without it camera rays
      // lost 3.5-6% on the H200 (again 5-7.5% at e7ac6b2: docs/results/h200-lean-steps); keeping the stack's top
      // entry in a register lost 5.5-9% (docs/results/h200-traversal-top).
      if (sp < RL_BVH_STACK) stack[sp++] = firstNearer ? child1 : child0;
      node = firstNearer ? child0 : child1;
    } else if (hit0 || hit1) {
      node = hit0 ? child0 : child1;
    } else {
      if (sp == 0u) break;
      node = stack[--sp];
    }
  }
  return hit;
}

#include "bvh_traverse_wide.glsl"

// The layout is GpuScene::bvhLayout (Settings::bvh), the same for every invocation of a dispatch: a uniform
// branch, no divergence. A pipeline may fix it instead (RL_SPEC_BVH_LAYOUT, to the same Settings::bvh), so
// that its code holds one traversal. On the H200 the megakernel gains from that (80 registers down to 72, a
// 4.6-8.8% shorter frame) and so does shade.comp's bounce loop, a megakernel over the live paths (512x256:
// Sponza 11.5% and the clutter room 5.5% shorter, the temple's openings 9% longer; docs/results/
// h200-onesweep-loop), where the split trace and shade stages took 4-20% longer with one traversal (the
// trace: 48 registers down to 39; docs/results/h200-binary-only). Those stages keep the default.
layout(constant_id = RL_SPEC_BVH_LAYOUT) const uint kBvhLayout = RL_BVH_FROM_SCENE;

HitRecord traverseSceneBvh(GpuScene scene, vec3 origin, vec3 dir, float tMax, bool anyHit) {
  const uint bvhLayout = kBvhLayout == RL_BVH_FROM_SCENE ? scene.bvhLayout : kBvhLayout;
  if (bvhLayout == RL_BVH_WIDE) return traverseBvhWide(scene, origin, dir, tMax, anyHit);
  return traverseBvh(scene, origin, dir, tMax, anyHit);
}

HitRecord traceClosest(GpuScene scene, vec3 origin, vec3 dir, float tMax) {
  return traverseSceneBvh(scene, origin, dir, tMax, false);
}

bool occluded(GpuScene scene, vec3 origin, vec3 dir, float tMax) {
  return traverseSceneBvh(scene, origin, dir, tMax, true).t > 0.0;
}

#endif
