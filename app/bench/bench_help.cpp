// `raylab bench --help`: the sweep's own flags, and the settings' axes from their rows (settings_table.h).
#include "app/bench/bench_sweep.h"
#include "renderer/settings/settings_table.h"

namespace raylab {

namespace {

// The help lines of the settings' own axes, in the table's order.
std::string settingAxesHelp() {
  std::string help;
  for (const SettingRow& r : settingRows())
    if (r.axis.flag) help += std::string("  --") + r.axis.flag + " " + r.axis.help + "\n";
  return help;
}

}  // namespace

std::string benchHelp() {
  return "usage: raylab bench [render flags] [sweep flags]\n"
         "  --cases SCENE@VIEW,...    default temple@alley,temple@hall,temple@openings\n"
         "  --scale-tris 1e4,1e5,...  one case per size for every bare temple-detail case (default case\n"
         "                            temple-detail@hall): the scene-scale sweep\n"
         "  --bounces 2,4,8,16        path lengths to sweep (each case renders its reference per count)\n"
         "  --sizes 512x256,1024x512  image sizes to sweep (default: --size's); with --spps, the paths per\n"
         "                            frame (width x height x spp) as an axis; a reference per size and spp\n"
         "  --spps 1,4                samples per frame to sweep (default: --spp's)\n"
         "  --strategies all|a,b,...  key strategies besides the baselines (default all)\n"
         "  --sorts radix,bitonic     sorts to sweep (default radix)\n"
         + settingAxesHelp() +
         "  --tracers compute,rt      tracers to sweep (default: --tracer's); rt labels start with \"rt \"\n"
         "  --bvhs binary,sbvh,wide   the compute tracer's BVH layouts to sweep (default: --bvh's); labels\n"
         "                            of a layout other than the default start with its name (\"binary \")\n"
         "  --sers on,hint            SER cells of the rt megakernel (by hit; by hit with a key hint)\n"
         "  --ser-hints two-point,... key strategies whose keys make the SER hint (default two-point)\n"
         "  --timed-frames N          measured frames per cell (default 8)\n"
         "  --warmup N                unmeasured frames first (default 2; at least half a second, and with\n"
         "                            --sort-policy auto until its plan stops exploring: auto is timed once it\n"
         "                            has decided, and its counting frame is one it sorted as planned)\n"
         "  --reference-spp N         samples of the megakernel reference image (default 64)\n"
         "  --camera-path FILE|builtin:NAME  every cell replays a moving camera (cases without @VIEW): after its\n"
         "                            warm-up, learned lengths and auto's costs start from nothing, each path\n"
         "                            frame is one fresh frame; the cell's times are over the path's frames\n"
         "                            (path_total_ms, path_mean_ms), each frame's figures one line of\n"
         "                            DIR/path_frames.jsonl (the first round's replay detailed unless\n"
         "                            --no-detail), DIR/motion.md the recovery after each cut; --frames N caps\n"
         "                            it; no reference image, so no --timed-frames, --reference-spp\n"
         "  --rounds N                measure every cell N times, in interleaved rounds (each round every cell\n"
         "                            once, in another fixed order), 1.." + std::to_string(kMaxRounds) + " (default " +
         std::to_string(kDefaultRounds) + "); the CSV's\n"
         "                            times are medians over the rounds with their spread (min, max, quartiles);\n"
         "                            DIR/resolution.txt names the cells it cannot tell apart\n"
         "  --no-detail               skip the untimed counting frame (no SIMT/accuracy figures)\n"
         "  --no-charts               write no charts (by default the sweep ends by running\n"
         "                            python3 app/bench/bench_charts.py DIR; RAYLAB_PYTHON picks the interpreter)\n"
         "  --out-dir DIR             results.jsonl (each cell's round as it ends), results.csv and cells.jsonl\n"
         "                            (one line per cell, its rounds made one; at the end), resolution.txt and\n"
         "                            sweep.json (the sweep and the git revision) (default bench-out). Not\n"
         "                            measured is an empty CSV cell, null in JSON, n/a on screen\n"
         "  --resume DIR              continue a sweep that was killed: run only the cells' rounds not yet in\n"
         "                            DIR/results.jsonl; the same flags as that sweep (or none: those in\n"
         "                            DIR/sweep.json), at the same revision, else exit 2\n"
         "  --sweep FILE              the same flags as `name = value` lines\n"
         "  --shard i/K               run only the cells n (0-based, in plan order) with n mod K = i, 0 <= i < K:\n"
         "                            one of K disjoint parts of the sweep, for K GPUs or hosts\n"
         "  --merge DIR... [--out-dir OUT]  put the K shard folders of one sweep back together (CSV, JSONL,\n"
         "                            charts; a camera path's frames and motion summaries); refuses folders of\n"
         "                            other sweeps or revisions, or a shard missing\n"
         "The megakernel and the unsorted wavefront are always measured, per tracer. The charts (needs\n"
         "matplotlib; without python3 or matplotlib the sweep says so and keeps its CSV) can be drawn again with\n"
         "  python3 app/bench/bench_charts.py DIR\n"
         "Exit status: 0 every cell measured and charted (or charts unavailable), 1 a cell failed, a result could\n"
         "not be written or a chart failed (results.csv and results.jsonl are kept), 2 a bad sweep (before any\n"
         "rendering), 4 validation errors.\n";
}

}  // namespace raylab
