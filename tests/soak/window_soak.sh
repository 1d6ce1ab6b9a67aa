#!/usr/bin/env bash
# Soak of the lab window: FRAMES frames (default 10000) of a 160x90 window rendering at full scale under
# Xvfb, with the strategy and heatmap changing every BLOCK frames (up to 250) so the panels, the
# speed-accuracy book and the renderer's rebuilds all keep running. The process's resident memory (VmRSS,
# from the script's `memory` action) is read after the warm-up (frame 500, or a third of a short run), at
# every tenth of the rest and at the end; OUT/soak.json has them with the device and the growth. It takes long (about a
# frame every 60-100 ms on two lavapipe cores), so it is a manual tool, not part of ctest; ctest runs a
# 300-frame version (tests/cli/gpu/window_soak_short.sh) that checks only that the report is well formed.
#
#   tests/soak/window_soak.sh build/raylab [FRAMES] [OUT]
#   SOAK_STEADY=1 tests/soak/window_soak.sh ...   the same settings throughout (fixed strategy, no heatmap):
#                                                 growth there is not pipeline rebuilds
set -eu
raylab=$(realpath "$1")
frames=${2:-10000}
out=${3:-soak-out}
[ "$frames" -ge 30 ] || { echo "window_soak: FRAMES must be at least 30" >&2; exit 2; }
command -v Xvfb >/dev/null || { echo "window_soak: needs Xvfb (apt-get install xvfb)" >&2; exit 2; }
on_xvfb="$(cd "$(dirname "${BASH_SOURCE[0]}")/../cli" && pwd)/on_xvfb.sh"
mkdir -p "$out"
out=$(realpath "$out")
warm=$(( frames >= 1500 ? 500 : frames / 3 ))
block=$(( warm / 2 < 250 ? warm / 2 : 250 ))
strategies=(fixed two-point gaussian none ema)
heatmaps=(none sort-key none traversal-steps)
if [ "${SOAK_STEADY:-0}" = 1 ]; then strategies=(fixed fixed fixed fixed fixed) heatmaps=(none none none none); fi
step=0
# Runs n frames in blocks (of `size`, default `block`), each block with the next strategy and heatmap.
run_frames() {
  local n=$1 size=${2:-$block} f
  while [ "$n" -gt 0 ]; do
    f=$(( n < size ? n : size ))
    printf 'set strategy %s\nset heatmap %s\nwait %d\n' "${strategies[step % 5]}" "${heatmaps[step % 4]}" "$f"
    step=$((step + 1)); n=$((n - f))
  done
}
# Between warm-up and end, a reading every tenth of the rest: a steady climb (a leak) and a step that then
# stays flat (a cache filling once) look different in the series.
every=$(( (frames - warm) / 10 > block ? (frames - warm) / 10 : block ))
{
  echo "set bounces 4"
  # The warm-up visits each of the 20 strategy x heatmap pairs (pipelines, buffers made once) at least once.
  run_frames "$warm" $(( warm / 20 > 0 ? warm / 20 : 1 ))
  echo "memory warm"
  done=$warm
  while [ $((done + every)) -lt "$frames" ]; do
    run_frames "$every"
    done=$((done + every))
    echo "memory at-$done"
  done
  run_frames $((frames - done))
  echo "memory end"
  echo "screenshot soak-end"
  echo "quit"
} >"$out/soak-script.txt"

start=$(date +%s)
code=0
(cd "$out" && bash "$on_xvfb" 640x480x24 "$raylab" --window-size 160x90 --scale 1 --screenshot-dir "$out" \
   --script "$out/soak-script.txt" >"$out/soak-stdout.txt" 2>"$out/soak-stderr.txt") || code=$?
seconds=$(( $(date +%s) - start ))
[ $code -eq 0 ] || { echo "window_soak: the window exited $code" >&2; tail -20 "$out/soak-stderr.txt" >&2; exit 1; }

python3 - "$out" "$frames" "$warm" "$seconds" "$(dirname "$0")/../../app" <<'PY'
import json, sys
out, frames, warm, seconds = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4])
sys.path.insert(0, sys.argv[5])
from checked_write import write_text  # app/checked_write.py: all of soak.json or none, else exit non-zero
reports, series = {}, []
for line in open(out + '/soak-stdout.txt'):
    line = line.strip()
    if line.startswith('{'):
        r = json.loads(line)
        if 'memory' in r:
            reports[r['memory']] = r
            series.append([r['frame'], r['vm_rss_kib']])
sidecar = json.load(open(out + '/soak-end.json'))
warm_r, end_r = reports['warm'], reports['end']
result = {
    'frames': end_r['frame'], 'warm_frame': warm_r['frame'], 'seconds': seconds,
    'window': '160x90', 'steady': __import__('os').environ.get('SOAK_STEADY', '0') == '1', 'render': '%dx%d' % (sidecar['settings']['width'], sidecar['settings']['height']),
    'device': sidecar['device'].get('name'), 'driver': sidecar['device'].get('driver'),
    'git_revision': sidecar['git_revision'],
    'warm_rss_kib': warm_r['vm_rss_kib'], 'end_rss_kib': end_r['vm_rss_kib'],
    # The kernel's VmHWM trails VmRSS by a little (per-thread counters), so the peak is the most of both.
    'growth_kib': end_r['vm_rss_kib'] - warm_r['vm_rss_kib'],
    'peak_rss_kib': max(max(r['vm_rss_kib'], r['vm_hwm_kib']) for r in reports.values()),
    # [frame, VmRSS KiB] from the warm-up on; the second half's growth tells a leak from a one-time step.
    'series': series,
    'second_half_growth_kib': end_r['vm_rss_kib'] - series[len(series) // 2][1],
}
write_text(out + '/soak.json', json.dumps(result, indent=1))
print('soak: %(frames)d frames, window %(window)s, render %(render)s, %(device)s (%(driver)s), %(seconds)d s: '
      'VmRSS %(warm_rss_kib)d KiB at frame %(warm_frame)d, %(end_rss_kib)d KiB at the end (%(growth_kib)+d KiB), '
      'peak %(peak_rss_kib)d KiB; second half %(second_half_growth_kib)+d KiB' % result)
PY
