// Two trees over the same triangles answer random rays alike: the same closest triangle at the same distance
// (a triangle in several leaves may be met in any of them) and the same shadow answers. Shared by the tests of
// the passes that reshape a tree (reinsertion, presplitting).
#pragma once

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "renderer/bvh/bvh.h"
#include "renderer/bvh/bvh_traverse_cpu.h"
#include "renderer/gpu_scene.h"

namespace raylab {

struct SameTreeHits {
  uint32_t hits = 0, blocked = 0;     // rays that hit, shadow rays blocked (what makes the comparison worth it)
  uint64_t stepsA = 0, stepsB = 0;    // the traversals' steps, summed
};

// `rays` rays from points in [-12, 12)^3 in random directions; shadow rays end at distance 4.
inline SameTreeHits expectSameHits(const std::vector<Triangle>& tris, const Bvh& a, const Bvh& b, int rays,
                                   unsigned seed) {
  const std::vector<gpu::GpuTriangle> inA = bvhOrderTriangles(tris, a.triangleOrder);
  const std::vector<gpu::GpuTriangle> inB = bvhOrderTriangles(tris, b.triangleOrder);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-12.0f, 12.0f);
  SameTreeHits out;
  for (int i = 0; i < rays; ++i) {
    const glm::vec3 o{u(rng), u(rng), u(rng)};
    const glm::vec3 d = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)));
    const CpuHit ha = traverseBinaryCpu(a.nodes, inA, o, d, 1e30f, false);
    const CpuHit hb = traverseBinaryCpu(b.nodes, inB, o, d, 1e30f, false);
    EXPECT_EQ(ha.t, hb.t) << "ray " << i;
    if (ha.t > 0.0f && hb.t > 0.0f) {
      ++out.hits;
      EXPECT_EQ(a.triangleOrder[ha.triangle], b.triangleOrder[hb.triangle]) << "ray " << i;
    }
    out.stepsA += ha.steps, out.stepsB += hb.steps;
    const bool sa = traverseBinaryCpu(a.nodes, inA, o, d, 4.0f, true).t > 0.0f;
    const bool sb = traverseBinaryCpu(b.nodes, inB, o, d, 4.0f, true).t > 0.0f;
    EXPECT_EQ(sa, sb) << "shadow ray " << i;
    out.blocked += sa;
  }
  return out;
}

}  // namespace raylab
