#!/usr/bin/env bash
# Issue 21's policy matrix again with the probes in shared frames (sort_policy.cpp): auto against always and never.
for f in .gl/*.deb; do dpkg -x $f /; done; ldconfig
tar -xJf .dev/bins.tar.xz && xz -dkf build-device/lib/*.xz
B=build-device
run() {  # name, size list, bounces
  ( time timeout $4 $B/raylab bench --cases temple@hall,.dev/sponza/Sponza.gltf@CameraMain,clutter:1000000@overview,temple-detail:1000000@hall \
    --strategies two-point --sort-policies always,auto --trace-shades split,fused --sizes $2 --bounces $3 \
    --timed-frames 8 --warmup 16 --reference-spp 1 --no-detail --no-charts --out-dir /tmp/$1 ) > $OUT/$1.log 2>&1
  cp /tmp/$1/results.jsonl $OUT/$1.jsonl; cp /tmp/$1/results.csv $OUT/$1.csv
}
run m4 512x256,2048x1024,4096x2048 4 230
run m8 512x256,2048x1024,4096x2048 8 260
echo done
