#!/usr/bin/env bash
# Device session (issue 21): the room at 8.4M paths, 8 bounces, auto with the two best keys and grids,
# against the best unsorted frame and the megakernel, both BVHs.
set -x
for f in .gl/*.deb; do dpkg -x $f /; done; ldconfig
xz -dkf build-device/lib/*.xz
R=build-device/raylab
( time timeout 330 $R bench --cases clutter:1000000@overview --size 4096x2048 --bounces 8 --timed-frames 6 --warmup 16 \
   --reference-spp 1 --no-charts --no-detail --strategies two-point,origin-direction --grids auto,32 --bvhs binary,wide \
   --trace-shades split,fused --sort-policies auto --out-dir /tmp/r ) > $OUT/room8.log 2>&1
cp /tmp/r/results.csv $OUT/room8.csv; cp /tmp/r/results.jsonl $OUT/room8.jsonl
echo done
