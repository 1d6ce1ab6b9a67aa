#include "renderer/stats_json.h"

namespace raylab {

using nlohmann::json;

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

json toJson(const CommandCounts& c) {
  return {{"dispatches", c.dispatches()},
          {"direct_dispatches", c.directDispatches},
          {"indirect_dispatches", c.indirectDispatches},
          {"barriers", c.barriers},
          {"size_writes", c.sizeWrites}};
}

json commandsJson(const CommandCounts& commands, uint32_t submissions) {
  json j = toJson(commands);
  j["submissions"] = submissions;
  return j;
}

namespace {
// The frame's fixed costs: its commands in total, per stage, and its host round trips.
json frameCommandsJson(const FrameStats& s) {
  json j = commandsJson(s.commands, s.submissions);
  json stages = json::array();
  for (const StageCommands& c : s.stageCommands) {
    json stage = toJson(c.counts);
    stage["stage"] = c.stage;
    stages.push_back(std::move(stage));
  }
  j["stages"] = std::move(stages);
  return j;
}
}  // namespace

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
                       {"mean_traversal_steps", loop(opt(x.meanTraversalSteps))},
                       {"trace_rays_per_second", opt(x.traceRaysPerSecond)},
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
          {"instrument_ms", s.instrumentMs()},
          {"work_ms", s.workMs()},
          {"wall_ms", s.wallMs},
          {"rays_traced", s.raysTraced},
          {"rays_per_second", s.raysPerSecond},
          {"key_bits", s.keyBits},
          {"length_cache_bytes", s.lengthCacheBytes},
          {"length_cache_occupancy", s.lengthCacheOccupancy < 0.0 ? json(nullptr) : json(s.lengthCacheOccupancy)},
          {"length_cache_resets", s.lengthCacheResets < 0 ? json(nullptr) : json(s.lengthCacheResets)},
          {"sort_scratch_bytes", s.sortScratchBytes},
          {"path_state_bytes", s.pathStateBytes},
          {"scene_bytes", s.sceneBytes},
          {"acceleration_structure_bytes", s.accelerationStructureBytes},
          {"stages", stages},
          {"commands", frameCommandsJson(s)},
          {"bounces", bounces},
          {"heatmap", toJson(s.heatmap)}};
}

json toJson(const DeviceInfo& d) {
  return {{"name", d.name},
          {"number", d.number},
          {"uuid", d.uuid},
          {"pci_bus", d.pciBus.empty() ? json(nullptr) : json(d.pciBus)},
          {"driver", d.driver},
          {"subgroup_size", d.subgroupSize},
          {"subgroup_partitioned", d.subgroupPartitioned},
          {"cpu", d.isCpu},
          {"ray_tracing", d.rayTracing ? json("yes") : json("no: lacks " + d.rayTracingMissing)},
          {"ser", d.ser ? json("yes") : json("no: lacks " + d.serMissing)},
          {"ser_reordering_hint", d.serReorderingHint}};
}

}  // namespace raylab
