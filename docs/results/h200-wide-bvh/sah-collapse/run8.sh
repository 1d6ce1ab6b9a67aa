#!/usr/bin/env bash
# Device session (issue 20): the SAH-optimal wide collapse (DP) against the greedy one: builds and traces.
set -x
for f in .gl/*.deb; do dpkg -x $f /; done; ldconfig
xz -dkf build-device/lib/*.xz
mkdir -p .dev/lib && cp build-device/lib/* .dev/lib/
S=.dev/sponza/Sponza.gltf
nvidia-smi --query-gpu=name,driver_version --format=csv > $OUT/gpu.txt 2>&1
for v in greedy dp03 dp10; do
  bin=build-device/raylab; cost=0.3; bvhs=wide
  case $v in greedy) bin=.dev/bin/raylab-greedy; bvhs=binary,wide;; dp10) cost=1.0;; esac
  ( time RL_TRI_COST=$cost timeout 110 $bin bench --cases $S@CameraMain,temple@hall,clutter:1000000@overview \
    --strategies two-point --bvhs $bvhs --trace-shades split --sizes 4096x2048 --bounces 4 --timed-frames 8 --warmup 3 \
    --reference-spp 1 --no-detail --no-charts --out-dir /tmp/v-$v ) > /tmp/v-$v.log 2>&1
  tail -3 /tmp/v-$v.log >> $OUT/variants.log
  sed "s/^/$v,/" /tmp/v-$v/results.csv >> $OUT/variants.csv
done
( time timeout 60 build-device/tests/raylab_bvh_report --repeats 3 $S temple-detail:1000000 clutter:1000000 ) > $OUT/bvh.jsonl 2>&1
( time timeout 60 build-device/tests/raylab_bvh_report --repeats 3 temple-detail:10000000 ) >> $OUT/bvh.jsonl 2>&1
echo done
