#!/usr/bin/env bash
# Absurd or malformed command-line values give a usage message and exit code 2, never a crash or a hang.
set -u
raylab="$1"
fail=0
expect() {
  local want="$1"; shift
  local out
  out=$(timeout 60 "$raylab" "$@" 2>&1); local got=$?
  if [ "$got" -ne "$want" ]; then
    echo "FAIL: raylab $* exited $got, expected $want"; echo "$out" | head -5; fail=1
  elif [ "$want" -eq 2 ] && ! grep -qi "usage\|must be\|expects\|unknown\|needs" <<<"$out"; then
    echo "FAIL: raylab $* gave no usage message"; fail=1
  fi
}
expect 2 render --size 0x100
expect 2 study
expect 2 study temple cornell
expect 2 study temple --sizes 0x0
expect 2 study temple --sizes 512x256,100000x1
expect 2 study temple --frobnicate
expect 2 study temple --out-dir
expect 2 study temple --rounds 0
expect 2 study temple --rounds many
expect 2 render --size 100
expect 2 render --size 100000x100
expect 2 render --size -5x10
expect 2 render --bounces 0
expect 2 render --bounces 1000
expect 2 render --spp abc
expect 2 render --frames 1.5
expect 2 render --seed -1
expect 2 render --kernel gpu
expect 2 render --strategy fastest
expect 2 render --sort quick
expect 2 render --grid 0
expect 2 render --sort-bits 33
expect 2 render --sort-bits -1
expect 2 render --fusion sideways
expect 2 render --compaction always
expect 2 render --trace-shade together
expect 2 render --bvh bogus
expect 2 bench --bvhs binary,bogus
out=$(timeout 60 "$raylab" render --bvh bogus 2>&1)
grep -qF -- "--bvh must be one of binary|sbvh|wide, got 'bogus'" <<<"$out" || { echo "FAIL: --bvh bogus: $out"; fail=1; }
expect 2 render --strategy fixed --sort tile --compaction none
expect 2 render --strategy two-point --sort-policy auto --trace-shade loop
out=$(timeout 60 "$raylab" render --strategy two-point --sort-policy auto --trace-shade loop 2>&1)
grep -qF -- "leaves --sort-policy auto no time per bounce" <<<"$out" || { echo "FAIL: loop with auto: $out"; fail=1; }
expect 2 render --learn-every 0
expect 2 render --learn-every 65
expect 2 render --grid 4x4
expect 2 render --grid 5000
expect 2 render --clamp nan
expect 2 render --clamp -1
expect 2 render --fixed-factor inf
expect 2 render --ema-alpha 0
expect 2 render --exposure
expect 2 render --no-such-flag
expect 2 render --scene nonsense
# The scene-scale family refuses sizes outside 1e4..3e7 and sizes that are not numbers, from the command
# line and from the bench's --cases and --scale-tris, before anything is built.
expect 2 render --scene temple-detail:abc
expect 2 render --scene temple-detail:9999
expect 2 render --scene temple-detail:1e9
expect 2 render --scene temple-detail:
expect 2 bench --cases temple-detail:-5@hall
expect 2 bench --scale-tris 1e4,5e7
expect 2 bench --scale-tris 1e4 --cases temple@hall
expect 2 bench --bounces 2,0
expect 2 bench --bounces 2,,x
expect 2 bench --rounds 0
expect 2 bench --rounds 101
expect 2 render --view nowhere
expect 2 frobnicate
expect 3 render --scene /nonexistent/missing.gltf
expect 2 render --device no-such-device --size 8x4
expect 2 render --size 8192x8192 --spp 64
expect 2 render --strategy fixed --heatmap cache-mean
expect 2 --frame-log
expect 2 --frame-log /nonexistent/folder/log.jsonl
expect 2 --render-budget-ms 0
expect 2 --render-budget-ms soon
expect 0 bench --help
"$raylab" bench --help 2>&1 | grep -q -- "--rounds N" || { echo "FAIL: bench --help lacks --rounds"; fail=1; }
# --quick says what it changes, on a GPU and on a CPU device (issue 34).
"$raylab" study --help 2>&1 | grep -q -- "--quick, CPU: sizes 128x64, 256x128; 4 bounces; two-point;" ||
  { echo "FAIL: study --help does not say what --quick changes"; fail=1; }
expect 0 render --help
expect 2 --window-size 1280
expect 2 --window-size 0x720
expect 2 --window-size 1280x100000
# raylab --help, -h and help list every mode and the window's own options, each option named once: the
# window's size is --window-size, --size is only the resolution.
for h in --help -h help; do
  out=$(timeout 60 "$raylab" $h 2>&1); got=$?
  [ $got -eq 0 ] || { echo "FAIL: raylab $h exited $got"; fail=1; }
  for word in "raylab render" "raylab sortbench" "raylab tracebench" "raylab bench" "raylab devices" --window-size --scale --script \
      --screenshot-dir --ini --reset --frame-log --render-budget-ms --strategy --sort-policy; do
    grep -qF -- "$word" <<<"$out" || { echo "FAIL: raylab $h does not list $word"; fail=1; }
  done
  grep -q -- "^  --size WxH *resolution" <<<"$out" || { echo "FAIL: raylab $h: --size is not the resolution"; fail=1; }
  dup=$(grep -oE -- "^  --[a-z-]+" <<<"$out" | sort | uniq -d)
  [ -z "$dup" ] || { echo "FAIL: raylab $h lists more than once: $dup"; fail=1; }
done
# (That the documented limits themselves are accepted needs a render: tests/cli/gpu/accepted_limits.sh.)
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT

# Screenshot sidecars given to --settings pass the same validation as the command line: each hostile
# value is refused with exit 2 and the flag's range, before any buffer is made.
sidecar() {  # KEY JSON-VALUE -> path of a sidecar with that one field changed
  python3 - "$dir" "$1" "$2" <<'PY'
import json, sys
d = {"scene": "temple", "view": "", "width": 32, "height": 16, "bounces": 2, "spp_per_frame": 1, "frames": 1,
     "seed": 1, "exposure": 1, "kernel": "wavefront", "strategy": "fixed", "sort": "radix", "grid": "auto",
     "grid_auto_cells": 64, "clamp_to_camera": False, "clamp_distance": 50, "fixed_factor": 0.5,
     "ema_alpha": 0.2, "gauss_outlier": 3, "gauss_reset": 20, "count_simt": False, "heatmap": "none",
     "heatmap_bounce": 1}
d[sys.argv[2]] = json.loads(sys.argv[3])
path = "%s/%s.json" % (sys.argv[1], sys.argv[2])
json.dump({"settings": d}, open(path, "w"))
print(path)
PY
}
hostile() {  # KEY VALUE MESSAGE
  local out; out=$(timeout 60 "$raylab" render --settings "$(sidecar "$1" "$2")" --out "$dir/x.png" 2>&1); local got=$?
  if [ $got -ne 2 ] || ! grep -qF -- "$3" <<<"$out"; then
    echo "FAIL: sidecar $1: $2 exited $got, expected 2 with '$3'"; echo "$out" | head -3; fail=1
  fi
}
hostile bounces -5 "--bounces must be between 1 and 32, got -5"
hostile width 1000000 "--size width must be between 1 and 8192, got 1000000"
hostile spp_per_frame 100000 "--spp must be between 1 and 64, got 100000"
hostile ema_alpha -3 "--ema-alpha must be between 0.001 and 1, got -3"
hostile clamp_distance -50 "--clamp must be between 0 and 1000000, got -50"
hostile grid_auto_cells 0 "must be between 1 and 1024, got 0"
hostile heatmap '"cache-mean"' "--heatmap cache-mean"
hostile strategy '"fastest"' "unknown kernel, strategy or sort"
hostile frames 1e12 "--frames must be between 1 and 4294967295"
hostile bvh '"bogus"' "'bvh' must be binary, sbvh or wide"
# A sweep file is command-line flags: the same checks.
printf 'bounces = -5\n' >"$dir/sweep.txt"
expect 2 bench --sweep "$dir/sweep.txt"
exit $fail
