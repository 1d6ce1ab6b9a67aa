// The structs in shaders/shared_types.h are read by GLSL with the scalar block layout; these asserts pin
// the host side to the same sizes and offsets the shaders assume.
#include <cstddef>
#include <stdexcept>
#include <utility>

#include <gtest/gtest.h>

#include "renderer/vk/shader_table.h"
#include "renderer/vk/spirv_reflect.h"
#include "shaders/heatmap_types.h"
#include "shaders/hit_query_types.h"
#include "shaders/key_types.h"
#include "shaders/shared_types.h"
#include "shaders/sort_types.h"

namespace raylab::gpu {

static_assert(sizeof(BvhNode) == 32);
static_assert(sizeof(BvhPairNode) == 64);  // four 16-byte words: the traversal's vector loads
static_assert(offsetof(BvhPairNode, yBounds) == 16);
static_assert(offsetof(BvhPairNode, child) == 48);
static_assert(offsetof(BvhPairNode, unused) == 56);
static_assert(offsetof(BvhNode, leftOrFirst) == 12);
static_assert(offsetof(BvhNode, triCount) == 28);
static_assert(sizeof(GpuTriangle) == 48);
static_assert(offsetof(GpuTriangle, e2) == 32);
static_assert(sizeof(GpuTriangleUv) == 24);
static_assert(sizeof(GpuMaterial) == 48);
static_assert(offsetof(GpuMaterial, emissive) == 16);
static_assert(offsetof(GpuMaterial, emitterPdfScale) == 40);
static_assert(sizeof(GpuTextureInfo) == 16);
static_assert(sizeof(GpuEmitter) == 8);
static_assert(sizeof(GpuCamera) == 64);
static_assert(offsetof(GpuCamera, up) == 48);
static_assert(sizeof(BvhWideNode) == 80);  // CWBVH's node size
static_assert(offsetof(BvhWideNode, exponents) == 12);
static_assert(offsetof(BvhWideNode, triBase) == 20);
static_assert(offsetof(BvhWideNode, meta) == 24);
static_assert(offsetof(BvhWideNode, qlo) == 32);
static_assert(offsetof(BvhWideNode, qhi) == 56);
// + the wide BVH's address, its layout word and pad, the leaf records' address, + the TLAS address (uvec2 in GLSL)
static_assert(sizeof(GpuScene) == 7 * 8 + 8 + 16 + 8 + 8 + 8 + 8);
static_assert(offsetof(GpuScene, wideNodes) == 80);
static_assert(offsetof(GpuScene, bvhLayout) == 88);
static_assert(offsetof(GpuScene, leafTriangles) == 96);
static_assert(offsetof(GpuScene, tlas) == 104);
static_assert(sizeof(GpuLeafTriangle) == 48);
static_assert(offsetof(GpuLeafTriangle, triangle) == 12);
static_assert(offsetof(GpuLeafTriangle, e1) == 16);
static_assert(offsetof(GpuLeafTriangle, e2) == 32);
static_assert(sizeof(GpuPathState) == 3 * 8);  // three 16-byte elements a path (RL_STATE_*)
static_assert(sizeof(GpuHits) == 4 * 8);
static_assert(offsetof(GpuFrame, scene) == 64);
static_assert(offsetof(GpuFrame, state) == 64 + sizeof(GpuScene));
static_assert(sizeof(PathStagePush) == 16);
static_assert(sizeof(HitQueryPush) == 4 * 8 + 8);

TEST(SharedLayout, StructSizesMatchScalarLayout) {
  // Scalar layout packs vec3 in 12 bytes with 4-byte alignment, as glm does on the host.
  EXPECT_EQ(sizeof(vec3), 12u);
  EXPECT_EQ(alignof(vec3), 4u);
  EXPECT_EQ(offsetof(GpuFrame, width), 64 + sizeof(GpuScene) + 2 * sizeof(GpuPathState) + sizeof(GpuHits) + 8 * 8);  // results .. keyParams
}

// Every shader's push-constant block, read from its SPIR-V, has the size of the C++ struct the host pushes
// (ComputePipeline checks the same when it builds a pipeline; this finds a drift without a device).
TEST(SharedLayout, PushConstantBlocksMatchTheHostStructs) {
  const std::pair<const char*, size_t> shaders[] = {
      {"generate", sizeof(PathStagePush)},       {"trace", sizeof(PathStagePush)},
      {"shade", sizeof(PathStagePush)},          {"accumulate", sizeof(PathStagePush)},
      {"tonemap", sizeof(PathStagePush)},        {"megakernel", sizeof(PathStagePush)},
      {"gather_path_state", sizeof(PathStagePush)},
      {"keys", sizeof(KeyPush)},                 {"key_oracle", sizeof(KeyPush)},
      {"key_learn", sizeof(KeyLearnPush)},       {"key_merge", sizeof(KeyLearnPush)},
      {"heatmap_gather", sizeof(HeatmapPush)},   {"heatmap_colorize", sizeof(HeatmapPush)},
      {"sort_radix_histogram", sizeof(SortRadixPush)}, {"sort_radix_scatter", sizeof(SortRadixPush)},
      {"sort_radix_scatter_partitioned", sizeof(SortRadixPush)},
      {"sort_radix_scan", sizeof(SortScanPush)}, {"sort_copy", sizeof(SortCopyPush)},
      {"sort_bitonic_local", sizeof(SortBitonicPush)}, {"sort_bitonic_global", sizeof(SortBitonicPush)},
      {"sort_onesweep_histogram", sizeof(SortOneSweepPush)}, {"sort_onesweep_pass", sizeof(SortOneSweepPush)},
      {"trace_rt", sizeof(PathStagePush)},       {"trace_rt_atomic", sizeof(PathStagePush)},
      {"shade_rt", sizeof(PathStagePush)},       {"megakernel_rt", sizeof(PathStagePush)},
      {"megakernel_rt_atomic", sizeof(PathStagePush)}, {"megakernel_ser", sizeof(RtSerPush)},
      {"rt_miss", 0},                            {"rt_shadow_miss", 0},
      {"rt_closest_hit", 0},                     {"hit_query", sizeof(HitQueryPush)},
  };
  for (const auto& [name, bytes] : shaders)
    EXPECT_EQ(raylab::spirvPushConstantBytes(raylab::shaderSpirv(name)), bytes) << name;
}

TEST(SharedLayout, ReflectionRejectsWhatIsNotSpirv) {
  const uint32_t junk[] = {1, 2, 3, 4, 5, 6};
  EXPECT_THROW(raylab::spirvPushConstantBytes(junk), std::runtime_error);
  // A truncated module: the header's magic, then an instruction claiming more words than remain.
  const uint32_t truncated[] = {0x07230203u, 0x00010500u, 0, 10, 0, (9u << 16) | 21u, 1};
  EXPECT_THROW(raylab::spirvPushConstantBytes(truncated), std::runtime_error);
}

}  // namespace raylab::gpu
