// raylab_bvh_report: builds the BVH of each scene named on the command line `repeats` times and prints one
// JSON line a scene (triangles, nodes, leaves, depth, SAH cost, build ms: median and min of the wall time,
// median of the process CPU time; the medians of the build's phases and of the wide BVH's collapse). It
// measures the builder on its own, without a Vulkan device or a render (docs/results/embree-bvh/README.md).
// Usage: raylab_bvh_report [--repeats N] [--max-leaf N] [--out FILE] SCENE...
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "renderer/bvh.h"
#include "renderer/bvh_wide.h"
#include "renderer/checked_write.h"
#include "scenes/scene_library.h"

int main(int argc, char** argv) {
  int repeats = 5;
  uint32_t maxLeaf = 0;  // 0: buildBvh's default
  std::string outPath;
  std::vector<std::string> scenes;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--repeats" && i + 1 < argc) {
      repeats = std::max(1, std::atoi(argv[++i]));
    } else if (a == "--max-leaf" && i + 1 < argc) {
      maxLeaf = static_cast<uint32_t>(std::max(1, std::atoi(argv[++i])));
    } else if (a == "--out" && i + 1 < argc) {
      outPath = argv[++i];
    } else {
      scenes.push_back(a);
    }
  }
  if (scenes.empty()) {
    std::fprintf(stderr, "usage: raylab_bvh_report [--repeats N] [--max-leaf N] [--out FILE] SCENE...\n");
    return 2;
  }
  std::string lines;
  try {
    for (const std::string& name : scenes) {
      raylab::Scene scene = raylab::loadSceneByName(name);
      std::vector<double> ms, cpuMs, primitivesMs, embreeMs, flattenMs, collapseMs;
      raylab::Bvh bvh;
      for (int r = 0; r < repeats; ++r) {
        // Process CPU time (every thread's) beside the wall time: on a shared machine the wall time says
        // as much about the other jobs as about the builder.
        std::clock_t cpu0 = std::clock();
        bvh = maxLeaf ? raylab::buildBvh(scene.triangles, maxLeaf) : raylab::buildBvh(scene.triangles);
        cpuMs.push_back(1000.0 * static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC);
        ms.push_back(bvh.stats.buildMs);
        primitivesMs.push_back(bvh.stats.primitivesMs);
        embreeMs.push_back(bvh.stats.embreeMs);
        flattenMs.push_back(bvh.stats.flattenMs);
        raylab::Bvh copy = bvh;  // the collapse rewrites the binary tree's leaf order
        collapseMs.push_back(raylab::collapseBvh(copy).stats.buildMs);
      }
      auto median = [](std::vector<double> v) {
        std::sort(v.begin(), v.end());
        return v[v.size() / 2];
      };
      uint32_t largestLeaf = 0;
      for (const raylab::gpu::BvhNode& n : bvh.nodes) largestLeaf = std::max(largestLeaf, n.triCount);
      nlohmann::json row = {{"scene", name},
                            {"triangles", scene.triangles.size()},
                            {"nodes", bvh.stats.nodeCount},
                            {"leaves", bvh.stats.leafCount},
                            {"largest_leaf", largestLeaf},
                            {"max_leaf_size", maxLeaf ? nlohmann::json(maxLeaf) : nlohmann::json("default")},
                            {"max_depth", bvh.stats.maxDepth},
                            {"sah_cost", bvh.stats.sahCost},
                            {"build_ms_median", median(ms)},
                            {"build_ms_min", *std::min_element(ms.begin(), ms.end())},
                            {"build_cpu_ms_median", median(cpuMs)},
                            {"primitives_ms_median", median(primitivesMs)},
                            {"embree_ms_median", median(embreeMs)},
                            {"flatten_ms_median", median(flattenMs)},
                            {"wide_collapse_ms_median", median(collapseMs)},
                            {"repeats", repeats}};
      lines += row.dump() + "\n";
      std::printf("%s\n", row.dump().c_str());
      std::fflush(stdout);
    }
    if (!outPath.empty()) raylab::writeFileChecked(outPath, lines);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "raylab_bvh_report: %s\n", e.what());
    return 1;
  }
  return 0;
}
