#!/usr/bin/env bash
# Device session (issue 21): the room at 8.4M paths, 4 bounces, auto with the best keys on a 32-cell grid.
set -x
for f in .gl/*.deb; do dpkg -x $f /; done; ldconfig
xz -dkf build-device/lib/*.xz
( time timeout 240 build-device/raylab bench --cases clutter:1000000@overview --size 4096x2048 --bounces 4 --timed-frames 8 --warmup 16 \
   --reference-spp 1 --no-charts --no-detail --strategies two-point,origin-direction --grids 32 --bvhs binary,wide \
   --trace-shades split --sort-policies auto --out-dir /tmp/r ) > $OUT/room4.log 2>&1
cp /tmp/r/results.csv $OUT/room4.csv; cp /tmp/r/results.jsonl $OUT/room4.jsonl
echo done
