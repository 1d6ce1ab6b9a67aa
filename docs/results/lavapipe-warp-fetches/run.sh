#!/usr/bin/env bash
# Issue 36 (why the sorted order pays on some scenes and not others), on lavapipe: device-independent counts of
# what the bounce rays' traversal reads, unsorted against sorted by two-point keys, from `tracebench --fetches`
# (the pair traversal's CPU twin over the very rays tracebench traces). At 2048x1024, the ray sets the H200 timed
# in h200-tree-variants (ba3d351; analyse.py joins them): through the sbvh tree (2k-SCENE.csv), in the oracle's
# order (the true hit point: the bound of what a landing-point key can order; oracle-SCENE.csv), and through the
# plain binary tree, also timed there (binary-SCENE.csv). At 1280x720 with shadow rays: the real-time size
# (720p-SCENE.csv). Then the 2048x1024 rays in every other key's order (key-STRATEGY-SCENE.csv). Lavapipe's times in them mean nothing: read the counts. Then prints analyse.py's tables.
# About 15 minutes on 2 cores.
set -euo pipefail
cd "$(dirname "$0")/../../.."
B=${B:-build/raylab}
out=docs/results/lavapipe-warp-fetches
run() {  # size kinds strategy bvh name scene args...
  local size=$1 kinds=$2 strategy=$3 bvh=$4 name=$5; shift 5
  $B tracebench "$@" --size $size --bvhs $bvh --kinds $kinds --sort-rays $strategy --repeat 1 --warmup 0 \
    --check 1024 --fetches --csv $out/$name.csv > /dev/null
}
while read -r name scene view; do
  run 2048x1024 bounce,bounce-sorted two-point sbvh 2k-$name --scene "$scene" ${view:+--view $view}
  run 2048x1024 bounce-sorted oracle sbvh oracle-$name --scene "$scene" ${view:+--view $view}
  run 2048x1024 bounce,bounce-sorted two-point binary binary-$name --scene "$scene" ${view:+--view $view}
  run 1280x720 bounce,bounce-sorted,shadow two-point sbvh 720p-$name --scene "$scene" ${view:+--view $view}
done <<'SCENES'
hall temple hall
openings temple openings
sponza ../shared/scenes/Sponza/Sponza.gltf CameraMain
detail temple-detail:1000000 hall
clutter clutter:1000000
SCENES
# The same 2048x1024 rays in the order of each other key that learns nothing (key-STRATEGY-SCENE.csv).
while read -r name scene view; do
  for key in origin direction origin-direction fixed; do
    run 2048x1024 bounce-sorted $key sbvh key-$key-$name --scene "$scene" ${view:+--view $view}
  done
done <<'SCENES'
sponza ../shared/scenes/Sponza/Sponza.gltf CameraMain
clutter clutter:1000000
detail temple-detail:1000000 hall
hall temple hall
SCENES
python3 $out/analyse.py
