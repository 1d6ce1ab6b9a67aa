#!/usr/bin/env bash
# Issue 36 (why the sorted order pays on some scenes and not others), on lavapipe: device-independent counts of
# what the bounce rays' traversal reads, unsorted against sorted by two-point keys, from `tracebench --fetches`
# (the pair traversal's CPU twin over the very rays tracebench traces). 2048x1024: the ray sets the H200 timed in
# h200-tree-variants (ba3d351; analyse.py joins them), and the same rays in the oracle's order (the true hit
# point: the bound of what a landing-point key can order); 1280x720 with shadow rays: the real-time size. Writes
# 2k-SCENE.csv, oracle-SCENE.csv and 720p-SCENE.csv here (lavapipe's times in them mean nothing: read the
# counts), then prints analyse.py's tables. About 6 minutes on 2 cores.
set -euo pipefail
cd "$(dirname "$0")/../../.."
B=${B:-build/raylab}
out=docs/results/lavapipe-warp-fetches
run() {  # size kinds strategy name scene args...
  local size=$1 kinds=$2 strategy=$3 name=$4; shift 4
  $B tracebench "$@" --size $size --bvhs sbvh --kinds $kinds --sort-rays $strategy --repeat 1 --warmup 0 \
    --check 1024 --fetches --csv $out/$name.csv > /dev/null
}
while read -r name scene view; do
  run 2048x1024 bounce,bounce-sorted two-point 2k-$name --scene "$scene" ${view:+--view $view}
  run 2048x1024 bounce-sorted oracle oracle-$name --scene "$scene" ${view:+--view $view}
  run 1280x720 bounce,bounce-sorted,shadow two-point 720p-$name --scene "$scene" ${view:+--view $view}
done <<'SCENES'
hall temple hall
openings temple openings
sponza ../shared/scenes/Sponza/Sponza.gltf CameraMain
detail temple-detail:1000000 hall
clutter clutter:1000000
SCENES
python3 $out/analyse.py
