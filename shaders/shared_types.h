// Structs shared by C++ and GLSL: data and macros only. Included by every compute shader and by the host
// code that fills the buffers; tests/cpu/test_shared_layout.cpp asserts sizes and offsets on the host so the
// two sides cannot drift. Everything uses the GLSL scalar block layout (vec3 = 12 bytes, align 4), which
// matches glm's C++ layout. Buffers are passed as device addresses (GL_EXT_buffer_reference), so no
// descriptor sets exist: a stage's push constants hold the addresses it reads and writes.
#ifndef RAYLAB_SHARED_TYPES_H
#define RAYLAB_SHARED_TYPES_H

#ifdef __cplusplus
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
namespace raylab::gpu {
using vec2 = glm::vec2;
using vec3 = glm::vec3;
using vec4 = glm::vec4;
using uint = uint32_t;
#define RL_REF(Type) uint64_t
// A device address that is not a buffer reference (an acceleration structure): uvec2 in GLSL, which
// accelerationStructureEXT() takes, so shaders that do not trace need no 64-bit integer extension.
#define RL_ADDRESS uint64_t
#else
#define RL_REF(Type) Type
#define RL_ADDRESS uvec2
#endif

// Work-group size of every path stage (one thread per path).
#define RL_PATH_GROUP_SIZE 64
// Largest BVH traversal stack.
#define RL_BVH_STACK 64
// A key no live path gets: terminated and missed paths sort last.
#define RL_DEAD_KEY 0xFFFFFFFFu

// ---- Named slots: every index into a GPU-visible array that both sides use is defined here, once.

// GpuFrame::counters: RL_COUNTER_STRIDE words per bounce (the megakernel uses bounce 0's), written by the
// trace stage (simt_counting.glsl) and the length cache's merge (key_merge.comp), cleared at the start of a
// frame and copied to the host once per frame.
#define RL_COUNTER_RAYS 0u          // rays traced
#define RL_COUNTER_SIMT_ACTIVE 1u   // active lanes summed over the subgroups' traversal iterations (countSimt)
#define RL_COUNTER_SIMT_SLOTS 2u    // subgroup traversal iterations (countSimt)
#define RL_COUNTER_CACHE_RESETS 3u  // length-cache entries whose past this bounce's learning dropped
#define RL_COUNTER_STRIDE 4u        // words per bounce
// Bounces the counters buffer has room for (SettingLimits::kMaxBounces).
#define RL_MAX_BOUNCES 32u

// GpuFrame::live: the live-path count and the indirect dispatch size for RL_PATH_GROUP_SIZE groups.
// Written by generate.comp (all paths), by the reorder after a sort (reorder_slot.glsl) and, with
// compaction, copied from the block shade appended to; trace and shade dispatch indirectly from
// RL_LIVE_DISPATCH.
#define RL_LIVE_COUNT 0u     // paths a stage must visit; paths at or past it count as finished
#define RL_LIVE_DISPATCH 1u  // [1..3]: group counts x, y, z for vkCmdDispatchIndirect
#define RL_LIVE_WORDS 4u
// Compaction (Settings::compaction): shade of bounce b appends the paths it keeps alive to block b + 1 of
// the same buffer (RL_LIVE_WORDS words each, reset to no paths at every slice's start); the host copies
// that block over block 0 before the next trace. So `live` holds 1 + RL_MAX_BOUNCES blocks.
#define RL_LIVE_APPEND RL_LIVE_WORDS

// Random-number streams (rng.glsl's rngSeed): independent uses within one bounce of one path.
#define RL_RNG_SHADE 0u   // BSDF and light sampling (shade, megakernel)
#define RL_RNG_KEY 1u     // the Gaussian key strategy's length sample (keys.glsl and its C++ twin)
#define RL_RNG_CAMERA 2u  // the camera ray's pixel jitter (generate, megakernel)

// The arrays of GpuPathState, in declaration order (PathBuffers allocates one buffer per array). One path
// is three aligned 16-byte elements; shaders read and write them only through path_state.glsl.
#define RL_STATE_ORIGIN 0      // xyz ray origin, w = solid-angle pdf of the BSDF sample (0: camera ray)
#define RL_STATE_DIRECTION 1   // xyz ray direction (unit), w = path id bits (RL_DEAD_PATH: finished)
#define RL_STATE_THROUGHPUT 2  // xyz path throughput, w = the key stage's predicted ray length (-1: none)
#define RL_STATE_ARRAY_COUNT 3
#define RL_STATE_BYTES_PER_PATH 48
// The path id of a finished path (GpuPathState::direction.w): no live path has it (ids < 2^32 - 1).
#define RL_DEAD_PATH 0xFFFFFFFFu

// Flattened BVH node: interior when triCount == 0 (children at leftOrFirst and leftOrFirst + 1),
// leaf otherwise (triangles leftOrFirst .. leftOrFirst + triCount - 1 in BVH order).
struct BvhNode {
  vec3 boundsMin;
  uint leftOrFirst;
  vec3 boundsMax;
  uint triCount;
};

// The binary BVH as the GPU walks it: each interior node stored as its two children's boxes, the layout of Aila
// and Laine (HPG 2009), so one 64-byte fetch of four aligned 16-byte words tests both children, and a leaf child
// is its leaf-entry range in the parent's slot (no fetch of its own). Built from the BvhNode tree on the host
// (renderer/bvh/bvh_pairs.h); the same leaves and BVH-order triangles, so every consumer of the order is unchanged.
struct BvhPairNode {
  vec4 xBounds;    // child 0 lo.x, hi.x, child 1 lo.x, hi.x
  vec4 yBounds;
  vec4 zBounds;
  uint child[2];   // the word the traversal carries: an interior child's pair-node index, a leaf child's
                   // RL_LEAF_WORD; RL_BVH_NO_CHILD (an empty scene) behind a box no ray enters
  uint unused[2];  // keeps the node at four 16-byte words
};
#define RL_BVH_NO_CHILD 0xFFFFFFFFu
// A leaf child's word: RL_LEAF_TAG, then its first leaf entry, then its count - 1 in the low RL_LEAF_COUNT_BITS
// bits. Stored ready in the node: against building it in the traversal's loop, the H200 traced 9-13% more
// camera rays and 3-6% more bounce rays a second (docs/results/h200-lean-steps). So a tree's leaf entries stay
// below RL_LEAF_ENTRY_LIMIT and its leaves at most 1 << RL_LEAF_COUNT_BITS entries (pairNodes checks both).
#define RL_LEAF_TAG 0x80000000u
#define RL_LEAF_COUNT_BITS 5u
#define RL_LEAF_ENTRY_LIMIT (1u << (31u - RL_LEAF_COUNT_BITS))
#define RL_LEAF_WORD(first, count) (RL_LEAF_TAG | ((first) << RL_LEAF_COUNT_BITS) | ((count) - 1u))
// A leaf word's first entry and entry count (the traversals and their CPU twin read them back).
#define RL_LEAF_FIRST(word) (((word) & ~RL_LEAF_TAG) >> RL_LEAF_COUNT_BITS)
#define RL_LEAF_COUNT(word) (((word) & ((1u << RL_LEAF_COUNT_BITS) - 1u)) + 1u)

// Compressed 8-wide BVH node (renderer/bvh/bvh_wide.h collapses the binary tree into these; traversal in
// shaders/bvh_traverse_wide.glsl), after Ylitie, Karras and Laine (HPG 2017): up to 8 children whose boxes are
// quantized to 8 bits per plane against the node's `origin` and a power-of-two scale per axis, so a child's box
// is origin + q * 2^e (rounded outwards when built: it always contains the child's exact box). A child slot is
// empty, an interior node or a leaf. Interior children are consecutive nodes from `childBase` in slot order, so
// an interior child's index is childBase plus the number of interior slots below it. A node's leaves are one
// contiguous block of BVH-order triangles (the collapse puts them there): leaf slot s holds triangles
// triBase + offset .. triBase + offset + count - 1, offset and count from its meta byte, no leaf record between.
// Slots are assigned by direction (slot s holds the child lying most towards the corner whose axis k is
// positive where bit k of s is set), so visiting slots in the order i ^ octant(ray) is roughly nearest first.
struct BvhWideNode {
  vec3 origin;
  uint exponents;  // byte k < 3: the biased exponent (IEEE bits 23..30) of axis k's scale 2^e; byte 3: the slots
                   // holding interior children (bit s: slot s)
  uint childBase;  // first interior child (index into the wide node array)
  uint triBase;    // bit 0 of the node's triangle mask: BVH-order triangle triBase (mod 2^32, see meta)
  uint meta[2];    // byte (s & 3) of word s >> 2, slot s's leaf: (count - 1) << 5 | offset, its triangles the
                   // mask bits offset .. offset + count - 1 (count <= 8, offset + count <= 32); 0: no leaf (an
                   // interior or empty slot). No leaf encodes as 0: the node's block starts with a leaf of 2 or
                   // more triangles, or, all its leaves single triangles, at offset 1 (triBase one below).
  uint qlo[6];     // 8-bit lower planes: byte (s & 3) of word 2 * axis + (s >> 2) is slot s's
  uint qhi[6];     // 8-bit upper planes, the same packing
};
#define RL_BVH_WIDTH 8u
// GpuScene::bvhLayout: which tree traceClosest and occluded walk (Settings::bvh). Both binary trees (without and
// with spatial splits) are pair nodes over leaf records: GpuSceneData::block points `nodes` and `leafTriangles`
// at the chosen one's.
#define RL_BVH_BINARY 0u
#define RL_BVH_WIDE 1u
// RL_SPEC_BVH_LAYOUT's default: the shader reads GpuScene::bvhLayout at run time and holds both traversals.
#define RL_BVH_FROM_SCENE 0xFFFFFFFFu

// A leaf entry of a binary tree: its triangle as the traversal tests it (v0 and two edges, GpuTriangle's floats)
// and the triangle's BVH-order index, which is what a hit reports. With spatial splits a triangle has an entry
// in every leaf its parts fell into (renderer/bvh/bvh_leaf_records.h).
struct GpuLeafTriangle {
  vec3 v0;
  uint triangle;  // BVH-order index (GpuTriangle, the emitters, the hits)
  vec3 e1;
  uint pad0;
  vec3 e2;
  uint pad1;
};

// Triangle in BVH order, stored for Moeller-Trumbore: v0 and the two edges.
struct GpuTriangle {
  vec3 v0;
  uint materialId;
  vec3 e1;
  uint sourceIndex;  // index in the scene's triangle list (for texture coordinates)
  vec3 e2;
  float area;
};

struct GpuTriangleUv {
  vec2 uv0;
  vec2 uv1;
  vec2 uv2;
};

struct GpuMaterial {
  vec3 baseColor;
  int baseColorTexture;  // -1: none
  vec3 emissive;
  float metallic;
  float roughness;
  float specularWeight;  // 0 turns the GGX lobe off (pure Lambert, e.g. the white furnace)
  float emitterPdfScale;  // 1 / total emitted power, times luminance(emissive): area pdf of light sampling
  float pad0;
};

struct GpuTextureInfo {
  uint offset;  // first texel in the texel buffer (RGBA8 packed in a uint)
  uint width;
  uint height;
  uint pad0;
};

// Emissive triangle for light sampling, chosen by a CDF over emitted power.
struct GpuEmitter {
  uint triangle;  // BVH-order triangle index
  float cdf;      // inclusive cumulative probability
};

struct GpuCamera {
  vec3 position;
  float tanHalfFovY;
  vec3 forward;
  float aspect;
  vec3 right;
  float pad0;
  vec3 up;
  float pad1;
};

#ifndef __cplusplus
// BvhPairNode as four aligned 16-byte words each, for the traversal's vector loads.
layout(buffer_reference, std430, buffer_reference_align = 16) buffer BvhPairQuads { vec4 v[]; };
layout(buffer_reference, scalar) buffer BvhWideNodeBuf { BvhWideNode v[]; };
// The same nodes as five aligned 16-byte words each (80 bytes, in BvhWideNode's order), for the traversal's
// vector loads: a struct of scalars is read field by field.
layout(buffer_reference, std430, buffer_reference_align = 16) buffer BvhWideNodeQuads { uvec4 v[]; };
layout(buffer_reference, scalar) buffer TriangleBuf { GpuTriangle v[]; };
// The same triangles as three aligned 16-byte words each (48 bytes: v0, e1, e2 in xyz, GpuTriangle's order), for
// the wide traversal's vector loads.
layout(buffer_reference, std430, buffer_reference_align = 16) buffer TriangleQuads { vec4 v[]; };
layout(buffer_reference, scalar) buffer TriangleUvBuf { GpuTriangleUv v[]; };
layout(buffer_reference, scalar) buffer MaterialBuf { GpuMaterial v[]; };
layout(buffer_reference, scalar) buffer TextureInfoBuf { GpuTextureInfo v[]; };
layout(buffer_reference, scalar) buffer EmitterBuf { GpuEmitter v[]; };
layout(buffer_reference, scalar) buffer UintBuf { uint v[]; };
layout(buffer_reference, scalar) buffer FloatBuf { float v[]; };
layout(buffer_reference, scalar) buffer Vec2Buf { vec2 v[]; };
layout(buffer_reference, scalar) buffer Vec4Buf { vec4 v[]; };
layout(buffer_reference, scalar) buffer UVec4Buf { uvec4 v[]; };
#endif

// Everything a traversal or shading function needs to know about the scene.
struct GpuScene {
  RL_REF(BvhPairQuads) nodes;  // the chosen binary BVH's pair nodes (BvhPairNode), the root's children first
  RL_REF(TriangleBuf) triangles;
  RL_REF(TriangleUvBuf) uvs;
  RL_REF(MaterialBuf) materials;
  RL_REF(TextureInfoBuf) textureInfos;
  RL_REF(UintBuf) texels;
  RL_REF(EmitterBuf) emitters;
  uint emitterCount;
  uint hasUvs;
  vec3 skyColor;
  float skyLightProbability;  // chance that next-event estimation samples the sky rather than a triangle
  // The wide BVH over the same BVH-order triangles (both trees are uploaded) and which one the traversal
  // walks: RL_BVH_BINARY or RL_BVH_WIDE, set per frame from Settings::bvh. A uniform branch in traceClosest
  // and occluded rather than a specialization constant: one pipeline per stage as before.
  RL_REF(BvhWideNodeBuf) wideNodes;
  uint bvhLayout;
  uint pad0;
  // The chosen binary BVH's leaf entries (GpuLeafTriangle), which its pair nodes' leaf children index.
  RL_REF(TriangleQuads) leafTriangles;
  RL_ADDRESS tlas;            // top-level acceleration structure of the rt tracer (0 with the compute tracer)
};

// One set of path state, structure of arrays of 16-byte elements (RL_STATE_* name each array and what its
// lanes hold). Two sets exist; after a sort, gather_path_state.comp gathers one into the other. Radiance is
// not carried: shade adds each bounce's contribution to results[pathId]; whether a path is alive is its id
// (RL_DEAD_PATH when finished), and slots at or past the live count (GpuFrame::live) are finished too.
// Read and write it only through path_state.glsl's accessors.
struct GpuPathState {
  RL_REF(Vec4Buf) origin;      // RL_STATE_ORIGIN
  RL_REF(Vec4Buf) direction;   // RL_STATE_DIRECTION
  RL_REF(Vec4Buf) throughput;  // RL_STATE_THROUGHPUT
};

// Trace output for one bounce, in the order of the current path state.
struct GpuHits {
  RL_REF(FloatBuf) t;          // hit distance, negative on a miss
  RL_REF(UintBuf) triangle;    // BVH-order triangle index
  RL_REF(Vec2Buf) barycentric;
  RL_REF(UintBuf) steps;       // traversal loop iterations of this path (virtual warp efficiency)
};

struct GpuFrame {
  GpuCamera camera;
  GpuScene scene;
  GpuPathState state[2];
  GpuHits hits;
  RL_REF(Vec4Buf) results;      // per path id: radiance summed over its bounces (xyz), 1 (w)
  RL_REF(Vec4Buf) accumulation; // per pixel: sum of radiance (xyz) and sample count (w)
  RL_REF(UintBuf) image;        // per pixel: tonemapped RGBA8
  RL_REF(UintBuf) counters;     // RL_COUNTER_* slots, RL_COUNTER_STRIDE words per bounce
  // RL_LIVE_* slots: the paths a stage must visit (all until a sort moved the finished ones behind the live
  // ones) and their indirect dispatch size.
  RL_REF(UintBuf) live;
  // The sort's pairs (key, path slot; sorted in place) and the key parameters (a KeyParamsBuf, zero when not
  // sorting): read by the stages Settings::fusion folds the key and reorder passes into.
  RL_REF(UintBuf) sortKeys;
  RL_REF(UintBuf) sortValues;
  RL_REF(UintBuf) keyParams;
  uint width;
  uint height;
  uint sppPerFrame;
  uint pathCount;
  uint frameIndex;
  uint bounceCount;
  uint seed;
  float exposure;
  uint dispatchRowGroups;  // work groups in a row of a dispatch (DeviceInfo::dispatchRowGroups, dispatch_grid.h)
};

#ifndef __cplusplus
layout(buffer_reference, scalar) buffer FrameBuf { GpuFrame f; };
#endif

// Push constants of the path stages: the frame block, this bounce and which state set is current.
struct PathStagePush {
  RL_REF(FrameBuf) frame;
  uint bounce;
  uint stateSet;
};

#ifdef __cplusplus
// The layouts the shaders assume (scalar block layout); ComputePipeline also checks every push-constant
// struct against the size the SPIR-V declares.
static_assert(sizeof(GpuPathState) == RL_STATE_ARRAY_COUNT * sizeof(uint64_t));
static_assert(offsetof(GpuPathState, throughput) == RL_STATE_THROUGHPUT * sizeof(uint64_t));
static_assert(RL_STATE_BYTES_PER_PATH == RL_STATE_ARRAY_COUNT * 16);
static_assert(sizeof(PathStagePush) == 16);
static_assert(offsetof(GpuScene, tlas) % 8 == 0 && sizeof(GpuScene) == offsetof(GpuScene, tlas) + 8);
static_assert(RL_COUNTER_CACHE_RESETS < RL_COUNTER_STRIDE && RL_LIVE_DISPATCH + 3 == RL_LIVE_WORDS);
}  // namespace raylab::gpu
#endif
#endif
