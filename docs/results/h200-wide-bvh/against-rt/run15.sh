#!/usr/bin/env bash
# Device session (issue 20, stop 33): the compute tracer (binary and wide BVH, SAH collapse) against the
# driver's ray-tracing pipeline on the scenes, with per-bounce stage times; temple-detail:10000000 too.
set -x
for f in .gl/*.deb; do dpkg -x $f /; done; ldconfig
xz -dkf build-device/lib/*.xz
S=.dev/sponza/Sponza.gltf
R=build-device/raylab
nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv > $OUT/gpu.txt 2>&1
( time timeout 330 $R bench --cases temple@hall,$S@CameraMain,temple-detail:1000000@hall \
    --tracers compute,rt --bvhs binary,wide --strategies two-point --sort-policies always --trace-shades split \
    --sizes 2048x1024,4096x2048 --bounces 4 --timed-frames 8 --warmup 3 --reference-spp 1 \
    --no-detail --no-charts --out-dir /tmp/a ) > $OUT/rt-vs-compute.log 2>&1
( time timeout 200 $R bench --cases temple-detail:10000000@hall \
    --tracers compute,rt --bvhs binary,wide --strategies two-point --sort-policies always --trace-shades split \
    --sizes 2048x1024 --bounces 4 --timed-frames 8 --warmup 3 --reference-spp 1 \
    --no-detail --no-charts --out-dir /tmp/b ) > $OUT/detail10m.log 2>&1
cp /tmp/a/results.csv $OUT/rt-vs-compute.csv; cp /tmp/a/results.jsonl $OUT/rt-vs-compute.jsonl
cp /tmp/b/results.csv $OUT/detail10m.csv; cp /tmp/b/results.jsonl $OUT/detail10m.jsonl
echo done
