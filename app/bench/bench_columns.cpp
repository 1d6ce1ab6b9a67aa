// The bench CSV's columns (app/bench/bench_results.h), in the library the tests link: the settings' columns are
// their rows' (renderer/settings/settings_table.h).
#include "app/bench/bench_results.h"

#include <algorithm>

#include "renderer/settings/settings_table.h"
#include "renderer/stages.h"

namespace raylab {

// The CSV's layout: settings columns (settings_table.h) among the results', in the order the CSV has always
// had; a setting's column not named here comes last.
std::vector<std::string> benchCsvColumns() {
  std::vector<std::string> columns{"device", "device_number", "device_uuid", "device_pci", "driver", "git_revision", "scene", "view", "width", "height", "bounces",
                                   "spp_per_frame", "kernel", "tracer", "ser", "ser_reordering_hint", "strategy", "sort",
                                   "label", "frame_ms_median", "frame_ms_min", "frame_ms_max", "trace_after_first_ms"};
  for (const StageInfo& s : kStages) columns.push_back(std::string(s.name) + "_ms");
  for (const char* c : {"rays_per_second", "trace_camera_rays_per_second", "trace_bounce_rays_per_second", "simt_efficiency", "virtual_warp_efficiency",
                        "virtual_warp_efficiency_after_first", "prediction_error_mean", "prediction_error_median",
                        "cell_hit_rate", "key_bits", "length_cache_bytes", "final_rel_mse", "sort_policy", "sorted_after",
                        "triangles", "bvh_nodes", "bvh_bytes", "scene_bytes", "bvh_build_ms", "scene_load_ms",
                        "tracer_setup_ms", "sort_bits", "learn_every", "fusion", "compaction", "trace_shade", "bvh",
                        "wide_bvh_nodes", "wide_bvh_bytes", "paths_per_frame",
                        // the spread over a sweep's rounds (app/bench/bench_rounds.h); empty with one round
                        "rounds", "frame_ms_q1", "frame_ms_q3", "trace_after_first_ms_min", "trace_after_first_ms_max",
                        // a camera path's replay (app/bench/bench_path.h); empty for still frames
                        "camera_path", "path_frames", "path_total_ms", "path_mean_ms",
                        // a frame's fixed costs (issue 36): its commands, the run's empty dispatch, their product
                        "dispatches", "indirect_dispatches", "barriers", "size_writes", "submissions",
                        "empty_dispatch_us", "fixed_cost_ms",
                        // how the radix scatter ranked (RadixRank resolved for the device)
                        "radix_rank"})
    columns.push_back(c);
  for (const SettingRow& r : settingRows())
    for (const std::string& c : r.csvColumns)
      if (std::find(columns.begin(), columns.end(), c) == columns.end()) columns.push_back(c);
  return columns;
}

}  // namespace raylab
