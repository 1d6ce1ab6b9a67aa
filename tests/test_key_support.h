// Helpers of the key-stage tests: a small box scene, random paths that include the awkward cases (dead
// paths, NaN/zero/infinite directions, origins outside the grid), and a fake frame block that holds just
// what the key shaders read (one path-state set, the trace's hit distances, a one-leaf BVH for the oracle,
// the counters key_merge.comp adds its resets to).
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "renderer/bvh/bvh_leaf_records.h"
#include "renderer/bvh/bvh_pairs.h"
#include "renderer/vk/gpu_buffer.h"
#include "renderer/reorder/key_functions.h"
#include "renderer/reorder/key_stage.h"
#include "renderer/vk/vk_context.h"
#include "scenes/scene.h"
#include "shaders/shared_types.h"

namespace raylab::test {

inline void addQuad(Scene& s, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
  Triangle t1, t2;
  t1.v[0] = a, t1.v[1] = b, t1.v[2] = c;
  t2.v[0] = a, t2.v[1] = c, t2.v[2] = d;
  s.triangles.push_back(t1);
  s.triangles.push_back(t2);
}

// The six faces of a box plus a floating quad inside; `flatY` squashes everything onto y = 0.
inline Scene boxScene(glm::vec3 lo = {0, 0, 0}, glm::vec3 hi = {10, 4, 6}, bool flatY = false) {
  Scene s;
  s.name = "key-test-box";
  s.materials.push_back(Material{});
  if (flatY) hi.y = lo.y;
  glm::vec3 p[8];
  for (int i = 0; i < 8; ++i) p[i] = {i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z};
  addQuad(s, p[0], p[1], p[3], p[2]);
  addQuad(s, p[4], p[6], p[7], p[5]);
  addQuad(s, p[0], p[4], p[5], p[1]);
  addQuad(s, p[2], p[3], p[7], p[6]);
  addQuad(s, p[0], p[2], p[6], p[4]);
  addQuad(s, p[1], p[5], p[7], p[3]);
  glm::vec3 c = 0.5f * (lo + hi), h = 0.2f * (hi - lo);
  addQuad(s, c + glm::vec3(-h.x, 0, -h.z), c + glm::vec3(h.x, 0, -h.z), c + glm::vec3(h.x, 0, h.z),
          c + glm::vec3(-h.x, 0, h.z));
  return s;
}

struct HostPaths {
  std::vector<glm::vec4> origin, direction;
  std::vector<uint32_t> pathId, alive;
  std::vector<float> hitT;
  size_t size() const { return origin.size(); }
};

// Half the origins on the scene's triangles (occupied cache cells), the rest anywhere in a box 20% larger
// than the scene (some outside the grid). With `awkward`, some paths are dead and some directions are NaN,
// zero, infinite or tiny.
inline HostPaths randomPaths(const Scene& scene, uint32_t n, uint32_t seed, bool awkward = true) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::normal_distribution<float> g(0.0f, 1.0f);
  Bounds b = scene.bounds();
  glm::vec3 lo = b.min - 0.1f * b.extent(), size = 1.2f * b.extent();
  HostPaths p;
  for (uint32_t i = 0; i < n; ++i) {
    glm::vec3 o;
    if (i % 2 == 0 && !scene.triangles.empty()) {
      const Triangle& t = scene.triangles[rng() % scene.triangles.size()];
      float a = u(rng), c = u(rng);
      if (a + c > 1.0f) a = 1.0f - a, c = 1.0f - c;
      o = t.v[0] + a * (t.v[1] - t.v[0]) + c * (t.v[2] - t.v[0]);
    } else {
      o = lo + glm::vec3(u(rng), u(rng), u(rng)) * size;
    }
    glm::vec3 d = glm::normalize(glm::vec3(g(rng), g(rng), g(rng)) + glm::vec3(1e-6f));
    uint32_t alive = 1;
    if (awkward) {
      uint32_t r = rng() % 20;
      if (r == 0) alive = 0;
      if (r == 1) d = glm::vec3(std::nanf(""), 0.0f, 1.0f);
      if (r == 2) d = glm::vec3(0.0f);
      if (r == 3) d = glm::vec3(INFINITY, 0.0f, 0.0f);
      if (r == 4) d = glm::vec3(1e-35f, 0.0f, 0.0f);
      if (r == 5) o = glm::vec3(std::nanf(""), 1.0f, 1.0f);
      if (r == 6) d = glm::vec3(0.0f, 0.0f, -1.0f);  // exact axis directions hit octahedral edges
    }
    p.origin.push_back(glm::vec4(o, 0.0f));
    p.direction.push_back(glm::vec4(d, 0.0f));
    p.pathId.push_back(rng());
    p.alive.push_back(alive);
    p.hitT.push_back(-1.0f);
  }
  return p;
}

// The GpuFrame block and the buffers it points to; unused addresses stay 0 (no key shader reads them).
class FakeFrame {
 public:
  FakeFrame(const VulkanContext& ctx, const Scene& scene, uint32_t capacity) : ctx_(&ctx), capacity_(capacity) {
    std::vector<gpu::GpuTriangle> tris;
    Bounds b = scene.bounds();
    for (const Triangle& t : scene.triangles)
      tris.push_back({t.v[0], 0u, t.v[1] - t.v[0], 0u, t.v[2] - t.v[0], 1.0f});
    Bvh oneLeaf;  // the whole scene one leaf, in the layout the traversal reads
    oneLeaf.nodes = {{b.min, 0u, b.max, static_cast<uint32_t>(tris.size())}};
    nodes_ = makeBufferFrom(ctx, pairNodes(oneLeaf));
    triangles_ = makeBufferFrom(ctx, tris);
    std::vector<uint32_t> order(tris.size());
    for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;
    leafTriangles_ = makeBufferFrom(ctx, leafRecords(scene.triangles, order, order));
    origin_ = GpuBuffer(ctx, capacity * sizeof(glm::vec4));
    direction_ = GpuBuffer(ctx, capacity * sizeof(glm::vec4));
    throughput_ = GpuBuffer(ctx, capacity * sizeof(glm::vec4));
    hitT_ = GpuBuffer(ctx, capacity * sizeof(float));
    keys = GpuBuffer(ctx, capacity * sizeof(uint32_t));
    values = GpuBuffer(ctx, capacity * sizeof(uint32_t));
    frameBlock_ = GpuBuffer(ctx, sizeof(gpu::GpuFrame));
    live_ = GpuBuffer(ctx, RL_LIVE_WORDS * sizeof(uint32_t));
    counters_ = GpuBuffer(ctx, RL_MAX_BOUNCES * RL_COUNTER_STRIDE * sizeof(uint32_t));
    clearCounters();
  }

  // GpuFrame::counters (RL_COUNTER_* slots per bounce): kept across upload(), as over a frame's bounces.
  void clearCounters() { counters_.uploadVector(std::vector<uint32_t>(RL_MAX_BOUNCES * RL_COUNTER_STRIDE, 0u)); }
  uint32_t counter(uint32_t bounce, uint32_t slot) const {
    return counters_.downloadVector<uint32_t>(RL_MAX_BOUNCES * RL_COUNTER_STRIDE)[bounce * RL_COUNTER_STRIDE + slot];
  }

  // `liveCount`: the live prefix of the last sort (GpuFrame::live); every path when not given.
  void upload(const HostPaths& p, uint32_t frameIndex = 3, uint32_t seed = 7, uint32_t stateSet = 0,
              std::optional<uint32_t> liveCount = std::nullopt) {
    ASSERT_LE(p.size(), capacity_);
    // The path-state layout (shared_types.h, RL_STATE_*): the path id in direction.w (RL_DEAD_PATH when
    // finished), the predicted length in throughput.w.
    std::vector<glm::vec4> direction(p.size()), throughput(p.size(), glm::vec4(1.0f, 1.0f, 1.0f, -1.0f));
    for (size_t i = 0; i < p.size(); ++i) {
      uint32_t id = p.alive[i] ? p.pathId[i] : RL_DEAD_PATH;
      ASSERT_TRUE(!p.alive[i] || id != RL_DEAD_PATH) << "a live path cannot have the dead id";
      direction[i] = glm::vec4(glm::vec3(p.direction[i]), std::bit_cast<float>(id));
    }
    origin_.uploadVector(p.origin);
    direction_.uploadVector(direction);
    throughput_.uploadVector(throughput);
    hitT_.uploadVector(p.hitT);
    gpu::GpuFrame f{};
    f.scene.nodes = nodes_.address();
    f.scene.leafTriangles = leafTriangles_.address();
    f.scene.triangles = triangles_.address();
    gpu::GpuPathState& s = f.state[stateSet];
    s.origin = origin_.address();
    s.direction = direction_.address();
    s.throughput = throughput_.address();
    f.hits.t = hitT_.address();
    std::vector<uint32_t> live(RL_LIVE_WORDS, 0u);
    live[RL_LIVE_COUNT] = liveCount.value_or(static_cast<uint32_t>(p.size()));
    live_.uploadVector(live);
    f.live = live_.address();
    f.counters = counters_.address();
    f.pathCount = static_cast<uint32_t>(p.size());
    f.frameIndex = frameIndex;
    f.seed = seed;
    frameBlock_.upload(&f, sizeof(f));
    frameIndex_ = frameIndex;
    seed_ = seed;
  }

  VkDeviceAddress address() const { return frameBlock_.address(); }
  uint32_t frameIndex() const { return frameIndex_; }
  uint32_t seed() const { return seed_; }
  std::vector<float> predicted(size_t n) const {
    std::vector<glm::vec4> t = throughput_.downloadVector<glm::vec4>(n);
    std::vector<float> out(n);
    for (size_t i = 0; i < n; ++i) out[i] = t[i].w;
    return out;
  }

  GpuBuffer keys, values;

 private:
  const VulkanContext* ctx_;
  uint32_t capacity_;
  uint32_t frameIndex_ = 0, seed_ = 0;
  GpuBuffer nodes_, triangles_, leafTriangles_, origin_, direction_, throughput_, hitT_, live_, counters_, frameBlock_;
};

struct KeyOutput {
  std::vector<uint32_t> keys, values;
  std::vector<float> predicted;
};

inline KeyOutput runKeys(const VulkanContext& ctx, KeyStage& stage, FakeFrame& frame, uint32_t n,
                         uint32_t bounce = 1, uint32_t stateSet = 0) {
  ctx.submitAndWait([&](VkCommandBuffer cmd) {
    stage.recordKeys(cmd, frame.address(), stateSet, bounce, frame.keys.address(), frame.values.address(), n,
                     nullptr);
  });
  return {frame.keys.downloadVector<uint32_t>(n), frame.values.downloadVector<uint32_t>(n), frame.predicted(n)};
}

inline void runLearn(const VulkanContext& ctx, KeyStage& stage, FakeFrame& frame, uint32_t n, uint32_t bounce = 1) {
  ctx.submitAndWait([&](VkCommandBuffer cmd) { stage.recordLearn(cmd, frame.address(), 0, bounce, n, nullptr); });
}

// Hit distances for learning: a smooth function of the ray (so cells learn something consistent) plus noise.
inline void setHits(HostPaths& p, float scale, uint32_t seed, float missFraction = 0.1f) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (size_t i = 0; i < p.size(); ++i) {
    glm::vec3 d(p.direction[i]);
    float base = scale * (0.3f + 0.2f * std::abs(d.x) + 0.1f * (d.y > 0.0f ? 1.0f : 0.0f));
    p.hitT[i] = u(rng) < missFraction ? -1.0f : base * (0.8f + 0.4f * u(rng));
  }
}

// Compares the GPU's keys and predicted lengths with the C++ twins' for the same inputs; returns the
// number of mismatches (0 expected) and checks every key's range.
inline uint32_t compareWithTwin(const KeyStage& stage, const FakeFrame& frame, const HostPaths& p,
                                const KeyOutput& out, uint32_t bounce, const std::vector<float>& oracleT = {}) {
  LengthCache::Contents cache = stage.downloadCache();
  KeyEnv env;
  env.frameIndex = frame.frameIndex();
  env.bounce = bounce;
  env.seed = frame.seed();
  env.slotKeys = cache.slotKeys;
  env.slotValues = cache.slotValues;
  env.entries = cache.entries;
  uint32_t strategy = strategyId(stage.strategy());
  uint32_t bits = stage.keyBits();
  uint32_t mismatches = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    KeyPath path{glm::vec3(p.origin[i]), glm::vec3(p.direction[i]), p.pathId[i], -1.0f};
    if (i < oracleT.size() && p.alive[i]) path.oracleT = oracleT[i];
    float len = 0.0f;
    uint32_t key = computeKey(strategy, stage.params(), env, path, p.alive[i], len);
    bool same = key == out.keys[i] && std::bit_cast<uint32_t>(len) == std::bit_cast<uint32_t>(out.predicted[i]);
    if (!same && ++mismatches <= 5)
      ADD_FAILURE() << toString(stage.strategy()) << " path " << i << ": gpu key " << out.keys[i] << " len "
                    << out.predicted[i] << ", twin key " << key << " len " << len;
    EXPECT_EQ(out.values[i], i);
    EXPECT_TRUE(std::isfinite(out.predicted[i])) << "path " << i;
    if (p.alive[i] == 0) {
      EXPECT_EQ(out.keys[i], RL_DEAD_KEY);
    } else {
      EXPECT_LT(uint64_t(out.keys[i]), uint64_t(1) << (bits - 1)) << toString(stage.strategy()) << " path " << i;
    }
  }
  return mismatches;
}

}  // namespace raylab::test
