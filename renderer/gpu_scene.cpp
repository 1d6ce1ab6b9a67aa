#include "renderer/gpu_scene.h"

#include <stdexcept>

#include "renderer/bvh/bvh_leaf_records.h"
#include "renderer/bvh/bvh_pairs.h"
#include "renderer/vk/vk_context.h"

namespace raylab {
namespace {

float luminance(const glm::vec3& c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

float triangleArea(const Triangle& t) { return 0.5f * glm::length(glm::cross(t.v[1] - t.v[0], t.v[2] - t.v[0])); }

}  // namespace

std::vector<gpu::GpuTriangle> bvhOrderTriangles(const std::vector<Triangle>& triangles,
                                                const std::vector<uint32_t>& triangleOrder) {
  std::vector<gpu::GpuTriangle> tris;
  tris.reserve(triangleOrder.size());
  for (uint32_t src : triangleOrder) {
    const Triangle& t = triangles[src];
    tris.push_back({t.v[0], t.material, t.v[1] - t.v[0], src, t.v[2] - t.v[0], triangleArea(t)});
  }
  return tris;
}

EmitterTable buildEmitterTable(const Scene& scene, const std::vector<uint32_t>& triangleOrder) {
  EmitterTable table;
  double total = 0.0;
  std::vector<double> power;
  for (uint32_t i = 0; i < triangleOrder.size(); ++i) {
    const Triangle& t = scene.triangles[triangleOrder[i]];
    const Material& m = scene.materials[t.material];
    double p = static_cast<double>(triangleArea(t)) * luminance(m.emissive);
    if (!m.isEmissive() || !(p > 0.0)) continue;
    table.emitters.push_back({i, 0.0f});
    power.push_back(p);
    total += p;
  }
  double running = 0.0;
  for (size_t i = 0; i < power.size(); ++i) {
    running += power[i];
    table.emitters[i].cdf = static_cast<float>(running / total);
  }
  if (!table.emitters.empty()) table.emitters.back().cdf = 1.0f;
  table.materialPdfScale.resize(scene.materials.size(), 0.0f);
  for (size_t m = 0; m < scene.materials.size(); ++m)
    if (total > 0.0) table.materialPdfScale[m] = static_cast<float>(luminance(scene.materials[m].emissive) / total);
  return table;
}

GpuSceneData::GpuSceneData(const VulkanContext& ctx, const Scene& scene, WideCollapse collapse,
                           uint32_t reinsertPasses, float presplit, bool keepHostTrees)
    : keepsHostTrees_(keepHostTrees), wideCollapse_(collapse), reinsertPasses_(reinsertPasses), presplit_(presplit) {
  for (const Triangle& t : scene.triangles)
    if (t.material >= scene.materials.size()) throw SceneLoadError(scene.name + ": triangle material out of range");
  Bvh bvh = buildBvh(scene.triangles);
  bvhStats_ = bvh.stats;
  // The collapse moves the leaves into its leaf order: before anything reads the order.
  const BvhWide wide = collapseBvh(bvh, 0, collapse);
  wideStats_ = wide.stats;
  bounds_ = scene.bounds();
  triangleCount_ = static_cast<uint32_t>(scene.triangles.size());

  const std::vector<gpu::GpuTriangle> tris = bvhOrderTriangles(scene.triangles, bvh.triangleOrder);
  std::vector<gpu::GpuTriangleUv> uvs;
  uvs.reserve(scene.triangles.size());
  for (uint32_t src : bvh.triangleOrder) {
    const Triangle& t = scene.triangles[src];
    bvhOrderVertices_.insert(bvhOrderVertices_.end(), {t.v[0], t.v[1], t.v[2]});
  }
  bool hasUvs = false;
  for (const Triangle& t : scene.triangles) {
    uvs.push_back({t.uv[0], t.uv[1], t.uv[2]});
    hasUvs = hasUvs || t.uv[0] != glm::vec2(0.0f) || t.uv[1] != glm::vec2(0.0f) || t.uv[2] != glm::vec2(0.0f);
  }

  EmitterTable lights = buildEmitterTable(scene, bvh.triangleOrder);
  std::vector<gpu::GpuMaterial> materials;
  for (size_t i = 0; i < scene.materials.size(); ++i) {
    const Material& m = scene.materials[i];
    int texture = m.baseColorTexture >= 0 && m.baseColorTexture < static_cast<int>(scene.textures.size()) &&
                          !scene.textures[m.baseColorTexture].rgba8.empty()
                      ? m.baseColorTexture
                      : -1;
    materials.push_back({m.baseColor, texture, m.emissive, m.metallic, m.roughness, m.specularWeight,
                         lights.materialPdfScale[i], 0.0f});
  }
  std::vector<gpu::GpuTextureInfo> textureInfos;
  std::vector<uint32_t> texels;
  for (const Texture& t : scene.textures) {
    textureInfos.push_back({static_cast<uint32_t>(texels.size()), t.width, t.height, 0});
    texels.insert(texels.end(), t.rgba8.begin(), t.rgba8.end());
  }

  auto add = [&](auto&& vec) {
    buffers_.push_back(makeBufferFrom(ctx, vec));
    return buffers_.back().address();
  };
  // Both binary trees read leaf records: the plain tree's are its own order (entry i, triangle i).
  auto upload = [&](HostPairTree tree, HostPairTree& kept) {
    const BinaryTree onGpu{add(tree.nodes), add(tree.entries)};
    if (keepHostTrees) kept = std::move(tree);
    return onGpu;
  };
  binary_ = upload({pairNodes(bvh), leafRecords(scene.triangles, bvh.triangleOrder, bvh.triangleOrder)}, hostBinary_);
  {
    Bvh split = buildBvh(scene.triangles, kSpatialSplitMaxLeafSize, 0, BvhSplits::Spatial, presplit);
    reinsertStats_ = reinsertOptimize(split, reinsertPasses);
    split.stats.buildMs += reinsertStats_.ms;
    splitStats_ = split.stats;
    split_ = upload({pairNodes(split), leafRecords(scene.triangles, split.triangleOrder, bvh.triangleOrder)}, hostSplit_);
  }
  block_.wideNodes = add(wide.nodes);
  block_.bvhLayout = RL_BVH_BINARY;  // block(layout) sets it
  block_.triangles = add(tris);
  block_.uvs = add(uvs);
  block_.materials = add(materials);
  block_.textureInfos = add(textureInfos);
  block_.texels = add(texels);
  block_.emitters = add(lights.emitters);
  block_.emitterCount = static_cast<uint32_t>(lights.emitters.size());
  block_.hasUvs = hasUvs ? 1u : 0u;
  block_.skyColor = scene.skyColor;
  bool sky = luminance(scene.skyColor) > 0.0f;
  // Light sampling splits between the sky and the emitters; with only one of them, all goes to it.
  block_.skyLightProbability = !sky ? 0.0f : (lights.emitters.empty() ? 1.0f : 0.5f);
}

const HostPairTree& GpuSceneData::hostTree(BvhLayout layout) const {
  if (!keepsHostTrees_) throw std::logic_error("GpuSceneData::hostTree: the scene was made without keepHostTrees");
  if (layout == BvhLayout::Wide) throw std::logic_error("GpuSceneData::hostTree: the wide tree has no pair nodes");
  return layout == BvhLayout::Sbvh ? hostSplit_ : hostBinary_;
}

uint64_t GpuSceneData::memoryBytes() const {
  uint64_t total = 0;
  for (const GpuBuffer& b : buffers_) total += b.size();
  return total;
}

}  // namespace raylab
