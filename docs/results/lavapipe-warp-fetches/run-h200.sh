#!/usr/bin/env bash
# For a session with the device (about 2 minutes): do the counts predict the time beyond the two-point order?
# The H200 traces the same 2048x1024 bounce rays unsorted, in two-point's order and in the oracle's
# (tracebench, sbvh, 10 rounds after 3 warm-up, interleaved in one submission), on the five scenes of
# README.md; two runs a scene. The counts say the oracle's order fills the clutter room's warps far better than
# two-point's (efficiency 0.381 against 0.269) and issues no fewer loads (4166 against 4143 bytes a ray): if the
# loads set the time, it is no faster; if the warp slots do, it gains 1.4x more. Read it with
# `python3 docs/results/lavapipe-warp-fetches/analyse.py $OUT/orders.csv`.
source docs/results/device-unpack.sh
B=build-device/raylab
for run in 1 2; do
  while read -r name scene view; do
    [ $name = sponza ] && scene=$S
    for key in two-point oracle; do
      $B tracebench --scene "$scene" ${view:+--view $view} --size 2048x1024 --bvhs sbvh --kinds bounce,bounce-sorted \
        --sort-rays $key --check 1024 --csv /tmp/t.csv > /tmp/t.log 2>&1 || echo "failed: $name $key" >> $OUT/errors.txt
      appendRows /tmp/t.csv $OUT/orders.csv run $run
    done
  done <<'SCENES'
hall temple hall
openings temple openings
sponza Sponza CameraMain
detail temple-detail:1000000 hall
clutter clutter:1000000
SCENES
done
