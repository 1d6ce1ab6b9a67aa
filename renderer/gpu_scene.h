// A scene on the GPU: its BVH (binary and wide), triangles in BVH order, materials, textures and the emitter CDF, plus the
// GpuScene block of addresses the shaders read.
#pragma once

#include <vector>

#include "renderer/bvh/bvh.h"
#include "renderer/bvh/bvh_reinsert.h"
#include "renderer/bvh/bvh_wide.h"
#include "renderer/vk/gpu_buffer.h"
#include "scenes/scene.h"
#include "shaders/shared_types.h"

namespace raylab {

class VulkanContext;

// The traversal a layout takes (GpuScene::bvhLayout, RL_SPEC_BVH_LAYOUT): both binary trees take the binary one.
inline uint32_t traversalOf(BvhLayout layout) { return layout == BvhLayout::Wide ? RL_BVH_WIDE : RL_BVH_BINARY; }

// A binary tree as its traversal reads it (GpuScene::nodes and leafTriangles), kept on the host for the CPU twin
// of that traversal (traversePairsCpu).
struct HostPairTree {
  std::vector<gpu::BvhPairNode> nodes;
  std::vector<gpu::GpuLeafTriangle> entries;
};

class GpuSceneData {
 public:
  // `collapse`: how the wide BVH is made (Settings::wideCollapse), which also decides the BVH order of the
  // triangles both layouts and the emitter table use. `reinsertPasses` (Settings::bvhReinsert): passes of
  // reinsertOptimize over the spatial-split tree. `presplit` (Settings::bvhPresplit): its cuts before that
  // tree's build (buildBvh). `keepHostTrees`: keep both binary trees' GPU form on the host too (hostTree).
  GpuSceneData(const VulkanContext& ctx, const Scene& scene, WideCollapse collapse, uint32_t reinsertPasses = 0,
               float presplit = 0.0f, bool keepHostTrees = false);

  // The block the shaders read, walking the tree `layout` (Settings::bvh: a frame's choice, not the scene's).
  gpu::GpuScene block(BvhLayout layout) const {
    gpu::GpuScene b = block_;
    b.bvhLayout = traversalOf(layout);
    const BinaryTree& tree = layout == BvhLayout::Sbvh ? split_ : binary_;
    b.nodes = tree.nodes;
    b.leafTriangles = tree.leafTriangles;
    return b;
  }
  // The binary tree `layout` names (Binary or Sbvh) as the GPU reads it; throws std::logic_error for the wide
  // layout or a scene made without keepHostTrees.
  const HostPairTree& hostTree(BvhLayout layout) const;
  const BvhBuildStats& bvhStats() const { return bvhStats_; }
  // The binary tree built again with spatial splits (BvhLayout::Sbvh) over the same BVH order.
  const BvhBuildStats& splitBvhStats() const { return splitStats_; }
  // The wide BVH collapsed from the binary one; both are on the GPU (Settings::bvh picks one per frame).
  const BvhWideStats& wideBvhStats() const { return wideStats_; }
  WideCollapse wideCollapse() const { return wideCollapse_; }
  uint32_t reinsertPasses() const { return reinsertPasses_; }
  float presplit() const { return presplit_; }
  // What the reinsertion did to the spatial-split tree (all zero without it; its time is in splitBvhStats'
  // buildMs).
  const ReinsertStats& reinsertStats() const { return reinsertStats_; }
  const Bounds& bounds() const { return bounds_; }
  uint32_t triangleCount() const { return triangleCount_; }
  uint32_t emitterCount() const { return block_.emitterCount; }
  uint64_t memoryBytes() const;
  // The triangles' corners in BVH order, three per triangle: the rt tracer's bottom-level structure is
  // built from them, so its primitive index is the BVH-order index the shaders use.
  const std::vector<glm::vec3>& bvhOrderVertices() const { return bvhOrderVertices_; }

 private:
  // A binary tree on the GPU: its pair nodes and leaf records (GpuScene::nodes, leafTriangles).
  struct BinaryTree {
    uint64_t nodes = 0, leafTriangles = 0;
  };
  std::vector<GpuBuffer> buffers_;
  gpu::GpuScene block_{};
  BinaryTree binary_, split_;
  bool keepsHostTrees_ = false;
  HostPairTree hostBinary_, hostSplit_;
  BvhBuildStats bvhStats_, splitStats_;
  BvhWideStats wideStats_;
  WideCollapse wideCollapse_;
  uint32_t reinsertPasses_ = 0;
  float presplit_ = 0.0f;
  ReinsertStats reinsertStats_;
  Bounds bounds_;
  uint32_t triangleCount_ = 0;
  std::vector<glm::vec3> bvhOrderVertices_;
};

// The triangles as the shaders read them (v0 and two edges), in BVH order: uploaded, and read by the CPU
// twin of the traversal (renderer/bvh/bvh_traverse_cpu.h).
std::vector<gpu::GpuTriangle> bvhOrderTriangles(const std::vector<Triangle>& triangles,
                                                const std::vector<uint32_t>& triangleOrder);

// Light-sampling tables of a scene, exposed for tests: emitter triangles (BVH order) with their CDF over
// emitted power, and each material's area pdf scale.
struct EmitterTable {
  std::vector<gpu::GpuEmitter> emitters;
  std::vector<float> materialPdfScale;
};
EmitterTable buildEmitterTable(const Scene& scene, const std::vector<uint32_t>& triangleOrder);

}  // namespace raylab
