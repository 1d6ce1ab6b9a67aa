// Steps, leaf visits and triangle tests a ray through raylab's trees, counted as the GLSL counts steps (pair nodes
// and leaves visited, nearer first), over the rays and triangles tracebench --export wrote. Not part of the build:
//   sed -e the two substitutions in run-harness.sh renderer/bvh/bvh.cpp > bvh_env.cpp   (weights from RL_INT_COST,
//   RL_SPLIT_BUDGET), then g++ -O2 -std=c++20 -DGLM_FORCE_RADIANS -DGLM_FORCE_DEPTH_ZERO_TO_ONE -I . -I build/generated
//   raylab_steps.cpp bvh_env.cpp renderer/bvh/bvh_reinsert.cpp -Wl,--allow-multiple-definition build/libraylab_core.a
//   -lembree3 -ltbb -lvulkan -ltinygltf -lstb -lpthread
// Usage: raylab_steps DIR [plain] KIND...   (RL_LEAF: leaf size; RL_REINSERT=N, RL_FRACTION: reinsertOptimize)
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>
#include "renderer/bvh/bvh.h"
#include "renderer/bvh/bvh_reinsert.h"
using namespace raylab;
static std::vector<float> readFloats(const std::string& path) {
  std::ifstream f(path, std::ios::binary | std::ios::ate);
  std::vector<float> v(size_t(f.tellg()) / 4);
  f.seekg(0);
  f.read(reinterpret_cast<char*>(v.data()), std::streamsize(v.size() * 4));
  return v;
}
int main(int argc, char** argv) {
  const std::string dir = argv[1];
  const std::vector<float> tf = readFloats(dir + "/triangles.bin");
  std::vector<Triangle> tris(tf.size() / 12);
  for (size_t i = 0; i < tris.size(); ++i)
    for (int k = 0; k < 3; ++k) tris[i].v[k] = glm::vec3(tf[i * 12 + k * 4], tf[i * 12 + k * 4 + 1], tf[i * 12 + k * 4 + 2]);
  const bool plain = argc > 3 && std::string(argv[2]) == "plain";
  Bvh bvh = plain ? buildBvh(tris) : buildBvh(tris, std::getenv("RL_LEAF") ? std::atoi(std::getenv("RL_LEAF")) : kSpatialSplitMaxLeafSize, 0, BvhSplits::Spatial);
  if (const char* ps = std::getenv("RL_REINSERT")) {
    const ReinsertStats r = reinsertOptimize(bvh, std::atoi(ps), std::getenv("RL_FRACTION") ? std::atof(std::getenv("RL_FRACTION")) : 0.01);
    std::printf("reinsert: %u passes, %u kept, %u moved, area %.3f -> %.3f, %.0f ms, depth %u\n", r.passes, r.kept, r.reinserted, r.areaBefore, r.areaAfter, r.ms, bvh.stats.maxDepth);
  }
  std::printf("raylab %s: %zu triangles, %u references, %zu nodes, %u leaves, SAH %.2f\n", plain ? "binary" : "sbvh",
              tris.size(), bvh.stats.references, bvh.nodes.size(), bvh.stats.leafCount, bvh.stats.sahCost);
  std::printf("kind,rays,mean_steps,mean_triangle_tests,warp_efficiency,hit_fraction\n");
  for (int k = plain ? 3 : 2; k < argc; ++k) {
    const std::string kind = argv[k];
    const std::vector<float> rf = readFloats(dir + "/rays-" + kind + ".bin");
    const size_t n = rf.size() / 8;
    const bool anyHit = kind == "shadow";
    uint64_t leaves = 0, steps = 0, tests = 0, hits = 0, slots = 0;
    uint32_t most = 0;
    for (size_t i = 0; i < n; ++i) {
      const float* r = &rf[i * 8];
      const glm::vec3 O(r[0], r[1], r[2]), D(r[4], r[5], r[6]), rD = 1.0f / D;
      float t = r[7];
      bool hit = false;
      uint32_t s = 0, node = 0, stack[128], sp = 0;
      while (true) {
        ++s;
        const gpu::BvhNode& nd = bvh.nodes[node];
        if (nd.triCount > 0) {
          ++leaves;
          bool done = false;
          for (uint32_t j = 0; j < nd.triCount && !done; ++j) {
            ++tests;
            const Triangle& tr = tris[bvh.triangleOrder[nd.leftOrFirst + j]];
            const glm::vec3 e1 = tr.v[1] - tr.v[0], e2 = tr.v[2] - tr.v[0], h = glm::cross(D, e2);
            const float a = glm::dot(e1, h);
            if (std::fabs(a) < 1e-12f) continue;
            const float f = 1.0f / a;
            const glm::vec3 sv = O - tr.v[0];
            const float u = f * glm::dot(sv, h);
            if (u < 0 || u > 1) continue;
            const glm::vec3 q = glm::cross(sv, e1);
            const float w = f * glm::dot(D, q);
            if (w < 0 || u + w > 1) continue;
            const float d = f * glm::dot(e2, q);
            if (d > 0 && d < t) { t = d; hit = true; if (anyHit) done = true; }
          }
          if (done || sp == 0) break;
          node = stack[--sp];
          continue;
        }
        auto enter = [&](const gpu::BvhNode& c, float& d) {
          const glm::vec3 a = (c.boundsMin - O) * rD, b = (c.boundsMax - O) * rD;
          const float tmin = std::max(std::max(std::min(a.x, b.x), std::min(a.y, b.y)), std::min(a.z, b.z));
          const float tmax = std::min(std::min(std::max(a.x, b.x), std::max(a.y, b.y)), std::max(a.z, b.z));
          d = tmin;
          return tmax >= tmin && tmin < t && tmax >= 0;
        };
        float d0, d1;
        uint32_t c0 = nd.leftOrFirst, c1 = nd.leftOrFirst + 1;
        const bool h0 = enter(bvh.nodes[c0], d0), h1 = enter(bvh.nodes[c1], d1);
        if (h0 && h1) {
          if (d1 < d0) std::swap(c0, c1);
          stack[sp++] = c1;
          node = c0;
        } else if (h0 || h1) node = h0 ? c0 : c1;
        else { if (sp == 0) break; node = stack[--sp]; }
      }
      steps += s, hits += hit, most = std::max(most, s);
      if (i % 32 == 31 || i + 1 == n) slots += 32ull * most, most = 0;
    }
    std::printf("%s,%zu,leaves %.4f,%.4f,%.4f,%.6f,%.6f\n", kind.c_str(), n, double(leaves) / n, double(steps) / n, double(tests) / n,
                double(steps) / double(slots), double(hits) / n);
  }
}
