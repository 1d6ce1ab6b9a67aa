// The structs in shaders/shared_types.h are read by GLSL with the scalar block layout; these asserts pin
// the host side to the same sizes and offsets the shaders assume.
#include <cstddef>

#include <gtest/gtest.h>

#include "shaders/shared_types.h"

namespace raylab::gpu {

static_assert(sizeof(BvhNode) == 32);
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
static_assert(sizeof(GpuScene) == 7 * 8 + 8 + 16);
static_assert(sizeof(GpuPathState) == 7 * 8);
static_assert(sizeof(GpuHits) == 4 * 8);
static_assert(offsetof(GpuFrame, scene) == 64);
static_assert(offsetof(GpuFrame, state) == 64 + sizeof(GpuScene));
static_assert(sizeof(PathStagePush) == 24);

TEST(SharedLayout, StructSizesMatchScalarLayout) {
  // Scalar layout packs vec3 in 12 bytes with 4-byte alignment, as glm does on the host.
  EXPECT_EQ(sizeof(vec3), 12u);
  EXPECT_EQ(alignof(vec3), 4u);
  EXPECT_EQ(offsetof(GpuFrame, width), 64 + sizeof(GpuScene) + 2 * sizeof(GpuPathState) + sizeof(GpuHits) + 5 * 8);
}

}  // namespace raylab::gpu
