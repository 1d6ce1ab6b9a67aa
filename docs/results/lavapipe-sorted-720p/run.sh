#!/usr/bin/env bash
# Issue 36, on lavapipe (device-independent counts): the frame's own bounce rays at 1280x720, unsorted (the
# default: compaction in shade) against two-point keys (radix, the gather fused into the trace), 4 bounces, one
# frame each; per bounce the warp efficiency and steps `render --stats` keeps. Writes counts.csv here.
set -euo pipefail
cd "$(dirname "$0")/../../.."
B=${B:-build/raylab}
out=docs/results/lavapipe-sorted-720p
tmp=$(mktemp -d)
echo "scene,view,strategy,bounce,rays,mean_traversal_steps,virtual_warp_efficiency" > $out/counts.csv
while read -r scene view; do
  for st in none two-point; do
    $B render --scene "$scene" ${view:+--view $view} --size 1280x720 --bounces 4 --strategy $st --frames 1 \
      --stats $tmp/s.json --out $tmp/s.png > /dev/null
    python3 - "$scene" "$view" $st $tmp/s.json >> $out/counts.csv <<'PY'
import json, sys
scene, view, st, path = sys.argv[1:5]
for b in json.load(open(path))['frames'][0]['bounces']:
    print(f"{scene.split('/')[-1]},{view},{st},{b['bounce']},{b['rays']},{b['mean_traversal_steps']},{b['virtual_warp_efficiency']}")
PY
  done
done <<'SCENES'
../shared/scenes/Sponza/Sponza.gltf CameraMain
temple hall
temple-detail:1000000 hall
clutter:1000000
SCENES
rm -r $tmp
