#!/usr/bin/env bash
# Device session (issue 20): the sorting study on the wide BVH, greedy against SAH-optimal collapse.
# Usage: bash .dev/run10.sh greedy|sah
set -x
for f in .gl/*.deb; do dpkg -x $f /; done; ldconfig
xz -dkf build-device/lib/*.xz
S=.dev/sponza/Sponza.gltf
how=$1
nvidia-smi --query-gpu=name,driver_version --format=csv > $OUT/gpu-$how.txt 2>&1
( time timeout 560 build-device/raylab bench --wide-collapse $how \
    --cases temple@hall,temple@openings,$S@CameraMain,temple-detail:1000000@hall,clutter:1000000@overview \
    --strategies two-point --sort-policies always --trace-shades split,fused --bvhs wide \
    --sizes 2048x1024,4096x2048 --bounces 4,8 --timed-frames 8 --warmup 4 --reference-spp 1 \
    --no-detail --no-charts --out-dir /tmp/s-$how ) > $OUT/study-$how.log 2>&1
cp /tmp/s-$how/results.csv $OUT/study-$how.csv
cp /tmp/s-$how/results.jsonl $OUT/study-$how.jsonl
echo done
