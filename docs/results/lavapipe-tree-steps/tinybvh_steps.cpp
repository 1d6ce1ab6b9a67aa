// Steps a ray through tinybvh's spatial-split tree (BuildHQ, the Aila-Laine node layout its GPU kernel
// traverses), counted as raylab's traversal counts them: one step per node visited, interior or leaf, nearer
// child first. Reads the files `raylab tracebench --export DIR` writes. Build against tinybvh's single header:
//   g++ -O2 -std=c++20 -I TINYBVH_DIR tinybvh_steps.cpp -o tinybvh_steps -lpthread   (tinybvh 1.6.7, 4735685)
// Usage: tinybvh_steps DIR KIND...   (TB_PLAIN=1: its binned SAH build instead; TB_OPT=N: then N passes of its
// Optimize). The rays and triangles: raylab tracebench ... --export DIR. (KIND: camera, bounce, bounce-sorted, shadow)
#define TINYBVH_IMPLEMENTATION
#include "tiny_bvh.h"

#include <chrono>
#include <cstdlib>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

using namespace tinybvh;

static std::vector<float> readFloats(const std::string& path) {
  std::ifstream f(path, std::ios::binary | std::ios::ate);
  if (!f) { std::fprintf(stderr, "cannot read %s\n", path.c_str()); std::exit(1); }
  std::vector<float> v(size_t(f.tellg()) / 4);
  f.seekg(0);
  f.read(reinterpret_cast<char*>(v.data()), std::streamsize(v.size() * 4));
  return v;
}

struct Count { uint32_t steps = 0, tris = 0, leaves = 0; float t = 1e30f; uint32_t prim = ~0u; };

// Moeller-Trumbore, as a closest-hit test (any hit for shadow rays).
static bool hitTri(const bvhvec4* v, uint32_t prim, const bvhvec3& O, const bvhvec3& D, float& t) {
  const bvhvec3 v0 = v[prim * 3], e1 = bvhvec3(v[prim * 3 + 1]) - v0, e2 = bvhvec3(v[prim * 3 + 2]) - v0;
  const bvhvec3 h = tinybvh_cross(D, e2);
  const float a = tinybvh_dot(e1, h);
  if (std::fabs(a) < 1e-12f) return false;
  const float f = 1.0f / a;
  const bvhvec3 s = O - v0;
  const float u = f * tinybvh_dot(s, h);
  if (u < 0 || u > 1) return false;
  const bvhvec3 q = tinybvh_cross(s, e1);
  const float w = f * tinybvh_dot(D, q);
  if (w < 0 || u + w > 1) return false;
  const float d = f * tinybvh_dot(e2, q);
  if (d > 0 && d < t) { t = d; return true; }
  return false;
}

static Count trace(const BVH_GPU& g, const bvhvec4* verts, bvhvec3 O, bvhvec3 D, float tMax, bool anyHit) {
  Count c;
  c.t = tMax;
  const bvhvec3 rD(1.0f / D.x, 1.0f / D.y, 1.0f / D.z);
  const BVH_GPU::BVHNode* node = &g.bvhNode[0];
  const BVH_GPU::BVHNode* stack[128];
  uint32_t sp = 0;
  while (true) {
    c.steps++;
    if (node->isLeaf()) {
      c.leaves++;
      for (uint32_t i = 0; i < node->triCount; ++i) {
        c.tris++;
        const uint32_t prim = g.bvh.primIdx[node->firstTri + i];
        if (hitTri(verts, prim, O, D, c.t)) { c.prim = prim; if (anyHit) return c; }
      }
      if (sp == 0) break;
      node = stack[--sp];
      continue;
    }
    auto enter = [&](bvhvec3 lo, bvhvec3 hi, float& d) {
      const bvhvec3 a = (lo - O) * rD, b = (hi - O) * rD;
      const float tmin = std::max(std::max(std::min(a.x, b.x), std::min(a.y, b.y)), std::min(a.z, b.z));
      const float tmax = std::min(std::min(std::max(a.x, b.x), std::max(a.y, b.y)), std::max(a.z, b.z));
      d = tmin;
      return tmax >= tmin && tmin < c.t && tmax >= 0;
    };
    float d0, d1;
    const bool h0 = enter(node->lmin, node->lmax, d0), h1 = enter(node->rmin, node->rmax, d1);
    const BVH_GPU::BVHNode *c0 = &g.bvhNode[node->left], *c1 = &g.bvhNode[node->right];
    if (h0 && h1) {
      if (d1 < d0) std::swap(c0, c1);
      stack[sp++] = c1;
      node = c0;
    } else if (h0 || h1) {
      node = h0 ? c0 : c1;
    } else {
      if (sp == 0) break;
      node = stack[--sp];
    }
  }
  return c;
}

int main(int argc, char** argv) {
  if (argc < 3) { std::fprintf(stderr, "usage: compare DIR KIND...\n"); return 2; }
  const std::string dir = argv[1];
  const std::vector<float> tf = readFloats(dir + "/triangles.bin");
  const uint32_t triCount = uint32_t(tf.size() / 12);
  const bvhvec4* verts = reinterpret_cast<const bvhvec4*>(tf.data());
  BVH_GPU g;
  const auto t0 = std::chrono::steady_clock::now();
  if (std::getenv("TB_PLAIN")) g.Build(verts, triCount); else g.BuildHQ(verts, triCount);
  if (std::getenv("TB_OPT")) g.Optimize(std::atoi(std::getenv("TB_OPT")));
  const double buildMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  std::printf("tinybvh %d.%d.%d %s%s: %u triangles, %u references (%.3f a triangle), %u nodes, SAH %.2f "
              "(c_trav %g, c_int %g), %.0f ms\n", TINY_BVH_VERSION_MAJOR, TINY_BVH_VERSION_MINOR,
              TINY_BVH_VERSION_SUB, std::getenv("TB_PLAIN") ? "Build" : "BuildHQ", std::getenv("TB_OPT") ? " + Optimize" : "",
              triCount, g.bvh.idxCount, double(g.bvh.idxCount) / triCount, g.bvh.usedNodes,
              g.SAHCost(), g.bvh.c_trav, g.bvh.c_int, buildMs);
  std::printf("kind,rays,mean_steps,mean_triangle_tests,warp_efficiency,hit_fraction,max_steps\n");
  for (int k = 2; k < argc; ++k) {
    const std::string kind = argv[k];
    const std::vector<float> rf = readFloats(dir + "/rays-" + kind + ".bin");
    const size_t n = rf.size() / 8;
    const bool anyHit = kind == "shadow";
    uint64_t leaves = 0, steps = 0, tris = 0, hits = 0, work = 0, slots = 0;
    uint32_t warpMost = 0, maxSteps = 0;
    for (size_t i = 0; i < n; ++i) {
      const float* r = &rf[i * 8];
      const Count c = trace(g, verts, bvhvec3(r[0], r[1], r[2]), bvhvec3(r[4], r[5], r[6]), r[7], anyHit);
      leaves += c.leaves, steps += c.steps, tris += c.tris, hits += c.prim != ~0u;
      work += c.steps, warpMost = std::max(warpMost, c.steps), maxSteps = std::max(maxSteps, c.steps);
      if (i % 32 == 31 || i + 1 == n) slots += 32ull * warpMost, warpMost = 0;
    }
    std::printf("%s,%zu,leaves %.4f,%.4f,%.4f,%.6f,%.6f,%u\n", kind.c_str(), n, double(leaves) / n, double(steps) / n, double(tris) / n,
                double(work) / double(slots), double(hits) / n, maxSteps);
  }
  return 0;
}
