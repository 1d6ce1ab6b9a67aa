#!/usr/bin/env bash
# Device session (issue 21): the policy matrix's 512x256 row again with 48 timed frames (the one miss was there).
set -x
for f in .gl/*.deb; do dpkg -x $f /; done; ldconfig
xz -dkf build-device/lib/*.xz
( time timeout 400 build-device/raylab bench --cases temple@hall,.dev/sponza/Sponza.gltf@CameraMain,clutter:1000000@overview,temple-detail:1000000@hall \
    --strategies two-point --sort-policies always,auto --trace-shades split,fused --sizes 512x256 --bounces 4,8 \
    --timed-frames 48 --warmup 16 --reference-spp 1 --no-detail --no-charts --out-dir /tmp/m ) > $OUT/m512.log 2>&1
cp /tmp/m/results.jsonl $OUT/m512.jsonl; cp /tmp/m/results.csv $OUT/m512.csv
echo done
