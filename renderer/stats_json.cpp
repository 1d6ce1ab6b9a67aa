#include "renderer/stats_json.h"

#include <cmath>
#include <stdexcept>

namespace raylab {

using nlohmann::json;

json toJson(const Settings& s) {
  return {
      {"scene", s.scene},
      {"view", s.view},
      {"width", s.width},
      {"height", s.height},
      {"bounces", s.bounces},
      {"spp_per_frame", s.sppPerFrame},
      {"frames", s.frames},
      {"seed", s.seed},
      {"exposure", s.exposure},
      {"kernel", toString(s.kernel)},
      {"strategy", toString(s.strategy)},
      {"sort", toString(s.sort)},
      {"sort_policy", toString(s.sortPolicy)},
      {"grid", s.grid.automatic ? json("auto") : json::array({s.grid.cells.x, s.grid.cells.y, s.grid.cells.z})},
      {"grid_auto_cells", s.grid.autoCells},
      {"clamp_to_camera", s.clampToCamera},
      {"clamp_distance", s.clampDistance},
      {"fixed_factor", s.fixedFactor},
      {"ema_alpha", s.emaAlpha},
      {"gauss_outlier", s.gaussOutlier},
      // JSON has no infinity: an unbounded reset threshold is written as null.
      {"gauss_reset", std::isfinite(s.gaussReset) ? json(s.gaussReset) : json(nullptr)},
      {"count_simt", s.countSimt},
      {"heatmap", toString(s.heatmap)},
      {"heatmap_bounce", s.heatmapBounce},
  };
}

Settings settingsFromJson(const json& j) {
  Settings s;
  auto need = [&](const char* key) -> const json& {
    if (!j.contains(key)) throw std::invalid_argument(std::string("settings: missing '") + key + "'");
    return j.at(key);
  };
  try {
    s.scene = need("scene").get<std::string>();
    s.view = need("view").get<std::string>();
    s.width = need("width").get<uint32_t>();
    s.height = need("height").get<uint32_t>();
    s.bounces = need("bounces").get<uint32_t>();
    s.sppPerFrame = need("spp_per_frame").get<uint32_t>();
    s.frames = need("frames").get<uint32_t>();
    s.seed = need("seed").get<uint32_t>();
    s.exposure = need("exposure").get<float>();
    auto kernel = parseKernel(need("kernel").get<std::string>());
    auto strategy = parseKeyStrategy(need("strategy").get<std::string>());
    auto sort = parseSortAlgorithm(need("sort").get<std::string>());
    if (!kernel || !strategy || !sort) throw std::invalid_argument("settings: unknown kernel, strategy or sort");
    s.kernel = *kernel;
    s.strategy = *strategy;
    s.sort = *sort;
    // Older sidecars have no sort policy: they sorted every bounce.
    if (j.contains("sort_policy")) {
      auto policy = parseSortPolicy(j.at("sort_policy").get<std::string>());
      if (!policy) throw std::invalid_argument("settings: unknown sort policy");
      s.sortPolicy = *policy;
    }
    const json& grid = need("grid");
    s.grid.automatic = grid.is_string();
    if (!s.grid.automatic) s.grid.cells = {grid.at(0).get<uint32_t>(), grid.at(1).get<uint32_t>(), grid.at(2).get<uint32_t>()};
    s.grid.autoCells = need("grid_auto_cells").get<uint32_t>();
    s.clampToCamera = need("clamp_to_camera").get<bool>();
    s.clampDistance = need("clamp_distance").get<float>();
    s.fixedFactor = need("fixed_factor").get<float>();
    s.emaAlpha = need("ema_alpha").get<float>();
    s.gaussOutlier = need("gauss_outlier").get<float>();
    s.gaussReset = need("gauss_reset").is_null() ? INFINITY : need("gauss_reset").get<float>();
    s.countSimt = need("count_simt").get<bool>();
    // Older sidecars have no heatmap fields: they showed the render.
    if (j.contains("heatmap")) {
      auto view = parseHeatmapView(j.at("heatmap").get<std::string>());
      if (!view) throw std::invalid_argument("settings: unknown heatmap view");
      s.heatmap = *view;
    }
    if (j.contains("heatmap_bounce")) s.heatmapBounce = j.at("heatmap_bounce").get<uint32_t>();
  } catch (const json::exception& e) {
    throw std::invalid_argument(std::string("settings: ") + e.what());
  }
  return s;
}

json toJson(const FrameStats& s) {
  json stages = json::array();
  for (const StageTime& t : s.stages) stages.push_back({{"stage", t.stage}, {"bounce", t.bounce}, {"ms", t.ms}});
  json bounces = json::array();
  for (size_t b = 0; b < s.bounces.size(); ++b) {
    const BounceStats& x = s.bounces[b];
    auto opt = [](double v) { return v < 0.0 ? json(nullptr) : json(v); };
    bounces.push_back({{"bounce", b},
                       {"rays", x.rays},
                       {"simt_efficiency", opt(x.simtEfficiency)},
                       {"virtual_warp_efficiency", opt(x.virtualWarpEfficiency)},
                       {"mean_traversal_steps", x.meanTraversalSteps},
                       {"prediction_error_mean", opt(x.predictionErrorMean)},
                       {"prediction_error_median", opt(x.predictionErrorMedian)},
                       {"cell_hit_rate", opt(x.cellHitRate)},
                       {"distinct_keys", x.distinctKeys},
                       {"sorted_after", x.sortedAfter},
                       {"sort_reason", x.sortReason}});
  }
  return {{"frame", s.frameIndex},
          {"samples_per_pixel", s.samplesPerPixel},
          {"gpu_frame_ms", s.frameMs},
          {"wall_ms", s.wallMs},
          {"rays_traced", s.raysTraced},
          {"rays_per_second", s.raysPerSecond},
          {"key_bits", s.keyBits},
          {"length_cache_bytes", s.lengthCacheBytes},
          {"length_cache_occupancy", s.lengthCacheOccupancy},
          {"sort_scratch_bytes", s.sortScratchBytes},
          {"path_state_bytes", s.pathStateBytes},
          {"scene_bytes", s.sceneBytes},
          {"stages", stages},
          {"bounces", bounces}};
}

json toJson(const DeviceInfo& d) {
  return {{"name", d.name}, {"driver", d.driver}, {"subgroup_size", d.subgroupSize}, {"cpu", d.isCpu}};
}

}  // namespace raylab
