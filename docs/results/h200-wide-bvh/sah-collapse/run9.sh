#!/usr/bin/env bash
# Device session (issue 20): greedy against SAH-optimal (DP) wide collapses, one binary, env knobs.
set -x
for f in .gl/*.deb; do dpkg -x $f /; done; ldconfig
xz -dkf build-device/lib/*.xz
S=.dev/sponza/Sponza.gltf
nvidia-smi --query-gpu=name,driver_version --format=csv > $OUT/gpu.txt 2>&1
run() {
  v=$1; shift
  ( time env "$@" timeout 110 build-device/raylab bench --cases $S@CameraMain,temple@hall,clutter:1000000@overview,temple-detail:1000000@overview \
    --strategies two-point --bvhs wide --trace-shades split --sizes 4096x2048 --bounces 4 --timed-frames 8 --warmup 3 \
    --reference-spp 1 --no-detail --no-charts --out-dir /tmp/v-$v ) > /tmp/v-$v.log 2>&1
  tail -3 /tmp/v-$v.log >> $OUT/variants.log
  sed "s/^/$v,/" /tmp/v-$v/results.csv >> $OUT/variants.csv
}
run greedy RL_GREEDY=1
run dp10 RL_TRI_COST=1.0
run dp03 RL_TRI_COST=0.3
run dp10n16 RL_TRI_COST=1.0 RL_NODE_TRIS=16
run greedy2 RL_GREEDY=1
echo done
