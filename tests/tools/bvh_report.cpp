// raylab_bvh_report: builds the BVH of each scene named on the command line `repeats` times and prints one
// JSON line a scene (triangles, nodes, leaves, depth, SAH cost, build ms: median and min of the wall time,
// median of the process CPU time; the medians of the build's phases and of the wide BVH's collapse). It
// measures the builder on its own, without a Vulkan device or a render (docs/results/embree-bvh/README.md).
// --hash adds hashes of the output (the binary tree as built; the wide tree with the binary tree's rewritten
// leaf order after the collapse; each with its stats but not the times), to check that a change to the
// builder leaves its output bit for bit the same.
// --threads N: the threads of the phases around Embree's build and of the collapse (default: the hardware's).
// Usage: raylab_bvh_report [--repeats N] [--max-leaf N] [--threads N] [--hash] [--out FILE] SCENE...
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "renderer/bvh/bvh.h"
#include "renderer/bvh/bvh_wide.h"
#include "renderer/bvh/bvh_wide_slots.h"
#include "renderer/checked_write.h"
#include "renderer/settings/settings_table.h"
#include "renderer/settings/settings_validation.h"
#include "scenes/scene_library.h"

namespace {

// FNV-1a over the arrays' bytes (BvhNode and BvhWideNode are all 4-byte fields: no padding bytes).
struct Hash {
  uint64_t h = 14695981039346656037ull;
  template <typename T>
  Hash& add(const std::vector<T>& v) {
    const auto* p = reinterpret_cast<const unsigned char*>(v.data());
    for (size_t i = 0; i < v.size() * sizeof(T); ++i) h = (h ^ p[i]) * 1099511628211ull;
    return *this;
  }
  Hash& add(std::vector<uint32_t> words) { return add<uint32_t>(words); }
  std::string hex() const {
    char buf[17];
    std::snprintf(buf, sizeof(buf), "%016llx", static_cast<unsigned long long>(h));
    return buf;
  }
};

std::string binaryHash(const raylab::Bvh& b) {
  const raylab::BvhBuildStats& s = b.stats;
  return Hash().add(b.nodes).add(b.triangleOrder)
      .add({s.nodeCount, s.leafCount, s.maxDepth, s.largestLeaf, s.maxLeafSize}).hex();
}

std::string wideHash(const raylab::Bvh& collapsed, const raylab::BvhWide& w) {
  return Hash().add(w.nodes).add(collapsed.nodes).add(collapsed.triangleOrder)
      .add({w.stats.nodeCount, w.stats.leafCount, w.stats.maxDepth}).hex();
}

}  // namespace

int main(int argc, char** argv) {
  int repeats = 5;
  uint32_t maxLeaf = 0;  // 0: buildBvh's default
  uint32_t threads = 0;  // 0: the hardware's
  bool hash = false;
  raylab::WideCollapse collapse = raylab::Settings{}.wideCollapse;
  std::string outPath;
  std::vector<std::string> scenes;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--repeats" && i + 1 < argc) {
      repeats = std::max(1, std::atoi(argv[++i]));
    } else if (a == "--max-leaf" && i + 1 < argc) {
      maxLeaf = static_cast<uint32_t>(std::max(1, std::atoi(argv[++i])));
    } else if (a == "--threads" && i + 1 < argc) {
      threads = static_cast<uint32_t>(std::max(1, std::atoi(argv[++i])));
    } else if (a == "--wide-collapse" && i + 1 < argc) {
      // The setting's own parser: its names and its message come from the settings table.
      raylab::Settings s;
      try {
        raylab::findSettingRow("wide-collapse")->parse(s, argv[++i]);
      } catch (const raylab::SettingsError& e) {
        std::fprintf(stderr, "raylab_bvh_report: %s\n", e.what());
        return 2;
      }
      collapse = s.wideCollapse;
    } else if (a == "--hash") {
      hash = true;
    } else if (a == "--out" && i + 1 < argc) {
      outPath = argv[++i];
    } else {
      scenes.push_back(a);
    }
  }
  if (scenes.empty()) {
    std::fprintf(stderr,
                 "usage: raylab_bvh_report [--repeats N] [--max-leaf N] [--threads N] [--wide-collapse greedy|sah] "
                 "[--hash] [--out FILE] SCENE...\n");
    return 2;
  }
  std::string lines;
  try {
    for (const std::string& name : scenes) {
      raylab::Scene scene = raylab::loadSceneByName(name);
      std::vector<double> ms, cpuMs, primitivesMs, embreeMs, flattenMs, collapseMs;
      raylab::Bvh bvh, collapsed;
      raylab::BvhWide wide;
      for (int r = 0; r < repeats; ++r) {
        // Process CPU time (every thread's) beside the wall time: on a shared machine the wall time says
        // as much about the other jobs as about the builder.
        std::clock_t cpu0 = std::clock();
        bvh = raylab::buildBvh(scene.triangles, maxLeaf ? maxLeaf : raylab::kDefaultMaxLeafSize, threads);
        cpuMs.push_back(1000.0 * static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC);
        ms.push_back(bvh.stats.buildMs);
        primitivesMs.push_back(bvh.stats.primitivesMs);
        embreeMs.push_back(bvh.stats.embreeMs);
        flattenMs.push_back(bvh.stats.flattenMs);
        collapsed = bvh;  // the collapse rewrites the binary tree's leaf order
        wide = raylab::collapseBvh(collapsed, threads, collapse);
        collapseMs.push_back(wide.stats.buildMs);
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
                            {"wide_collapse", raylab::toString(collapse)},
                            {"wide_nodes", wide.stats.nodeCount},
                            {"wide_leaf_slots", wide.stats.leafCount},
                            {"wide_sah_cost", raylab::wideSahCost(wide, collapsed)},
                            {"repeats", repeats}};
      if (hash) row["hash_binary"] = binaryHash(bvh), row["hash_wide"] = wideHash(collapsed, wide);
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
