#include "renderer/stats_json.h"

#include <cmath>
#include <stdexcept>

#include "renderer/settings_validation.h"

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
      {"tracer", toString(s.tracer)},
      {"bvh", toString(s.bvh)},
      {"ser", toString(s.ser)},
      {"strategy", toString(s.strategy)},
      {"sort", toString(s.sort)},
      {"sort_policy", toString(s.sortPolicy)},
      {"sort_bits", s.sortBits},
      {"fusion", toString(s.fusion)},
      {"compaction", toString(s.compaction)},
      {"trace_shade", toString(s.traceShade)},
      {"grid", s.grid.automatic ? json("auto") : json::array({s.grid.cells.x, s.grid.cells.y, s.grid.cells.z})},
      {"grid_auto_cells", s.grid.autoCells},
      {"clamp_to_camera", s.clampToCamera},
      {"clamp_distance", s.clampDistance},
      {"fixed_factor", s.fixedFactor},
      {"ema_alpha", s.emaAlpha},
      {"gauss_outlier", s.gaussOutlier},
      // JSON has no infinity: an unbounded reset threshold is written as null.
      {"gauss_reset", std::isfinite(s.gaussReset) ? json(s.gaussReset) : json(nullptr)},
      {"learn_every", s.learnEvery},
      {"count_simt", s.countSimt},
      {"heatmap", toString(s.heatmap)},
      {"heatmap_bounce", s.heatmapBounce},
      {"heatmap_key_colour", toString(s.heatmapKeyColour)},
      {"heatmap_scale", toString(s.heatmapScale)},
      {"heatmap_range", {{"locked", s.heatmapRange.locked}, {"min", s.heatmapRange.min}, {"max", s.heatmapRange.max}}},
  };
}

// Numbers are range-checked as JSON numbers, before they become uint32_t or float (-5 must not wrap to
// 4294967291, 1e300 must not become inf), with the command line's ranges and messages.
// A field of `j` older sidecars may lack: `absent` then, else one of the names `parse` takes.
template <class E>
E optionalEnum(const json& j, const char* key, E absent, std::optional<E> (*parse)(const std::string&), const char* names) {
  if (!j.contains(key)) return absent;
  std::optional<E> value = parse(j.at(key).get<std::string>());
  if (!value) throw SettingsError(std::string("settings: '") + key + "' must be " + names + ", got " + j.at(key).dump());
  return *value;
}

Settings settingsFromJson(const json& j) {
  Settings s;
  namespace R = ranges;
  auto need = [&](const char* key) -> const json& {
    if (!j.contains(key)) throw SettingsError(std::string("settings: missing '") + key + "'");
    return j.at(key);
  };
  auto numberOf = [](const char* key, const json& v) {
    if (!v.is_number()) throw SettingsError(std::string("settings: '") + key + "' must be a number, got " + v.dump());
    return v.get<double>();
  };
  auto uintAt = [&](const char* key, const json& v, const NumberRange& r) {
    double d = numberOf(key, v);
    checkUint(r, d, formatNumber(d));
    return static_cast<uint32_t>(d);
  };
  auto uintField = [&](const char* key, const NumberRange& r) { return uintAt(key, need(key), r); };
  auto floatField = [&](const char* key, const NumberRange& r) {
    double d = numberOf(key, need(key));
    checkFloat(r, d, formatNumber(d));
    return static_cast<float>(d);
  };
  try {
    s.scene = need("scene").get<std::string>();
    s.view = need("view").get<std::string>();
    s.width = uintField("width", R::width);
    s.height = uintField("height", R::height);
    s.bounces = uintField("bounces", R::bounces);
    s.sppPerFrame = uintField("spp_per_frame", R::spp);
    s.frames = uintField("frames", R::frames);
    s.seed = uintField("seed", R::seed);
    s.exposure = floatField("exposure", R::exposure);
    auto kernel = parseKernel(need("kernel").get<std::string>());
    auto strategy = parseKeyStrategy(need("strategy").get<std::string>());
    auto sort = parseSortAlgorithm(need("sort").get<std::string>());
    if (!kernel || !strategy || !sort) throw SettingsError("settings: unknown kernel, strategy or sort");
    s.kernel = *kernel;
    s.strategy = *strategy;
    s.sort = *sort;
    // Older sidecars have no sort policy: they sorted every bounce.
    if (j.contains("sort_policy")) {
      auto policy = parseSortPolicy(j.at("sort_policy").get<std::string>());
      if (!policy) throw std::invalid_argument("settings: unknown sort policy");
      s.sortPolicy = *policy;
    }
    // Older sidecars have no sort bits: they sorted all of them.
    if (j.contains("sort_bits")) s.sortBits = uintField("sort_bits", R::sortBits);
    // Older sidecars lack these; the value is what those versions did. Without fusion every reorder stage was
    // a pass of its own, without compaction finished paths stayed in their slots, and without trace_shade
    // trace and shade were always two dispatches.
    s.fusion = optionalEnum(j, "fusion", Fusion::None, &parseFusion, "none, keys, gather or both");
    s.compaction = optionalEnum(j, "compaction", Compaction::None, &parseCompaction, "none or shade");
    s.traceShade = optionalEnum(j, "trace_shade", TraceShade::Split, &parseTraceShade, "split or fused");
    // Before the wide BVH every sidecar's compute tracer walked the binary tree.
    s.bvh = optionalEnum(j, "bvh", BvhLayout::Binary, &parseBvhLayout, "binary or wide");
    const json& grid = need("grid");
    if (grid.is_string() && grid.get<std::string>() != "auto")
      throw SettingsError("settings: 'grid' must be \"auto\" or [x, y, z], got " + grid.dump());
    s.grid.automatic = grid.is_string();
    if (!s.grid.automatic) {
      if (!grid.is_array() || grid.size() != 3)
        throw SettingsError("settings: 'grid' must be \"auto\" or [x, y, z], got " + grid.dump());
      for (int a = 0; a < 3; ++a) s.grid.cells[a] = uintAt("grid", grid.at(a), R::gridCells);
    }
    s.grid.autoCells = uintField("grid_auto_cells", R::gridAutoCells);
    s.clampToCamera = need("clamp_to_camera").get<bool>();
    s.clampDistance = floatField("clamp_distance", R::clamp);
    s.fixedFactor = floatField("fixed_factor", R::fixedFactor);
    s.emaAlpha = floatField("ema_alpha", R::emaAlpha);
    s.gaussOutlier = floatField("gauss_outlier", R::gaussOutlier);
    s.gaussReset = need("gauss_reset").is_null() ? INFINITY : floatField("gauss_reset", R::gaussReset);
    // Older sidecars have no learning stride: they learned from every path.
    if (j.contains("learn_every")) s.learnEvery = uintField("learn_every", R::learnEvery);
    s.countSimt = need("count_simt").get<bool>();
    // Older sidecars have no tracer or SER: they used the compute tracer.
    if (j.contains("tracer")) {
      auto tracer = parseTracer(j.at("tracer").get<std::string>());
      if (!tracer) throw std::invalid_argument("settings: unknown tracer");
      s.tracer = *tracer;
    }
    if (j.contains("ser")) {
      auto ser = parseSer(j.at("ser").get<std::string>());
      if (!ser) throw std::invalid_argument("settings: unknown ser");
      s.ser = *ser;
    }
    // Older sidecars have no heatmap fields: they showed the render.
    if (j.contains("heatmap")) {
      auto view = parseHeatmapView(j.at("heatmap").get<std::string>());
      if (!view) throw SettingsError("settings: unknown heatmap view");
      s.heatmap = *view;
    }
    if (j.contains("heatmap_bounce")) s.heatmapBounce = uintAt("heatmap_bounce", j.at("heatmap_bounce"), R::heatmapBounce);
    // Older sidecars have no heatmap colouring: they hashed keys on a linear, per-frame range.
    if (j.contains("heatmap_key_colour")) {
      auto colour = parseHeatmapKeyColour(j.at("heatmap_key_colour").get<std::string>());
      if (!colour) throw SettingsError("settings: unknown heatmap_key_colour (cell|rank|hash)");
      s.heatmapKeyColour = *colour;
    } else if (j.contains("heatmap")) {
      s.heatmapKeyColour = HeatmapKeyColour::Hash;
    }
    if (j.contains("heatmap_scale")) {
      auto scale = parseHeatmapScale(j.at("heatmap_scale").get<std::string>());
      if (!scale) throw SettingsError("settings: unknown heatmap_scale (linear|log)");
      s.heatmapScale = *scale;
    }
    if (j.contains("heatmap_range")) {
      const json& r = j.at("heatmap_range");
      if (!r.is_object()) throw SettingsError("settings: 'heatmap_range' must be {locked, min, max}, got " + r.dump());
      s.heatmapRange.locked = r.at("locked").get<bool>();
      auto end = [&](const char* key, const NumberRange& range) {
        double d = numberOf(key, r.at(key));
        checkFloat(range, d, formatNumber(d));
        return static_cast<float>(d);
      };
      s.heatmapRange.min = end("min", R::heatmapRangeMin);
      s.heatmapRange.max = end("max", R::heatmapRangeMax);
    }
  } catch (const json::exception& e) {
    throw SettingsError(std::string("settings: ") + e.what());
  }
  validateSettings(s);  // what no single field shows (paths per frame)
  return s;
}

json toJson(const HeatmapStats& h) {
  if (h.view.empty()) return nullptr;
  json j = {{"view", h.view},
            {"bounce", h.bounce},
            {"range", json::array({h.min, h.max})},
            {"range_locked", h.rangeLocked},
            {"frame_range", json::array({h.frameMin, h.frameMax})},
            {"unit", h.unit},
            {"scale", h.scale},
            {"key_colour", h.keyColour.empty() ? json(nullptr) : json(h.keyColour)},
            {"pixels", h.pixels},
            {"pixels_with_value", h.pixelsWithValue},
            {"pixels_without_path", h.pixelsWithoutPath},
            {"pixels_without_value", h.pixelsWithoutValue}};
  if (!h.noValueMeaning.empty()) j["no_value_means"] = h.noValueMeaning;
  if (!h.emptyReason.empty()) j["empty_reason"] = h.emptyReason;
  return j;
}

json toJson(const FrameStats& s) {
  json stages = json::array();
  for (const StageTime& t : s.stages) stages.push_back({{"stage", t.stage}, {"bounce", t.bounce}, {"ms", t.ms}});
  json bounces = json::array();
  for (size_t b = 0; b < s.bounces.size(); ++b) {
    const BounceStats& x = s.bounces[b];
    auto opt = [](double v) { return v < 0.0 ? json(nullptr) : json(v); };
    // Figures of our traversal loop: the rt tracer has none, and says so instead of writing zeros.
    auto loop = [&](json v) { return s.traversalStatsUnavailable.empty() ? v : json(s.traversalStatsUnavailable); };
    bounces.push_back({{"bounce", b},
                       {"rays", x.rays},
                       {"simt_efficiency", loop(opt(x.simtEfficiency))},
                       {"virtual_warp_efficiency", loop(opt(x.virtualWarpEfficiency))},
                       {"mean_traversal_steps", loop(x.meanTraversalSteps)},
                       {"prediction_error_mean", opt(x.predictionErrorMean)},
                       {"prediction_error_median", opt(x.predictionErrorMedian)},
                       {"cell_hit_rate", opt(x.cellHitRate)},
                       {"distinct_keys", x.distinctKeys < 0 ? json(nullptr) : json(x.distinctKeys)},
                       {"sorted_after", x.sortedAfter},
                       {"sort_reason", x.sortReason}});
  }
  return {{"frame", s.frameIndex},
          {"samples_per_pixel", s.samplesPerPixel},
          {"gpu_frame_ms", s.frameMs},
          {"stage_sum_ms", s.stageSumMs()},
          {"unattributed_ms", s.unattributedMs()},
          {"wall_ms", s.wallMs},
          {"rays_traced", s.raysTraced},
          {"rays_per_second", s.raysPerSecond},
          {"key_bits", s.keyBits},
          {"length_cache_bytes", s.lengthCacheBytes},
          {"length_cache_occupancy", s.lengthCacheOccupancy},
          {"sort_scratch_bytes", s.sortScratchBytes},
          {"path_state_bytes", s.pathStateBytes},
          {"scene_bytes", s.sceneBytes},
          {"acceleration_structure_bytes", s.accelerationStructureBytes},
          {"stages", stages},
          {"bounces", bounces},
          {"heatmap", toJson(s.heatmap)}};
}

json toJson(const DeviceInfo& d) {
  return {{"name", d.name},
          {"driver", d.driver},
          {"subgroup_size", d.subgroupSize},
          {"cpu", d.isCpu},
          {"ray_tracing", d.rayTracing ? json("yes") : json("no: lacks " + d.rayTracingMissing)},
          {"ser", d.ser ? json("yes") : json("no: lacks " + d.serMissing)},
          {"ser_reordering_hint", d.serReorderingHint}};
}

}  // namespace raylab
