#!/usr/bin/env bash
# Device session (issue 20, stop 33): the sorting study at the final revision, binary and wide BVH (SAH collapse,
# hit-mask box tests), split and fused trace+shade, 4 and 8 bounces, 2.1M and 8.4M paths, the scenes and
# the cluttered room.
set -x
for f in .gl/*.deb; do dpkg -x $f /; done; ldconfig
xz -dkf build-device/lib/*.xz
S=.dev/sponza/Sponza.gltf
R=build-device/raylab
nvidia-smi --query-gpu=name,driver_version --format=csv > $OUT/gpu.txt 2>&1
for b in 4 8; do
  ( time timeout 280 $R bench \
      --cases temple@hall,temple@openings,$S@CameraMain,temple-detail:1000000@hall,clutter:1000000@overview \
      --strategies two-point --sort-policies always --trace-shades split,fused --bvhs binary,wide \
      --sizes 2048x1024,4096x2048 --bounces $b --timed-frames 8 --warmup 3 --reference-spp 1 \
      --no-detail --no-charts --out-dir /tmp/s$b ) > $OUT/study-$b.log 2>&1
  cp /tmp/s$b/results.csv $OUT/study-$b.csv; cp /tmp/s$b/results.jsonl $OUT/study-$b.jsonl
done
echo done
