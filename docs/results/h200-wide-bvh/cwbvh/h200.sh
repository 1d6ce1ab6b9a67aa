#!/usr/bin/env bash
# One device session: GPU-AV proofs, the wide-BVH invariants, the binary-against-wide heart bench.
set -x
for f in .gl/*.deb; do dpkg -x $f /; done; dpkg -x .dev/vvl.deb /; ldconfig
tar -xJf .dev/bins.tar.xz && xz -dkf build-device/lib/*.xz
B=build-device
nvidia-smi --query-gpu=name,driver_version --format=csv > $OUT/gpu.txt 2>&1
( time RAYLAB_VALIDATE=gpu-av $B/tests/raylab_gpu_tests --gtest_filter='ValidationChecks.GpuAssisted*' ) > $OUT/gpuav.log 2>&1
( time RAYLAB_VALIDATE=1 timeout 120 $B/tests/raylab_gpu_tests --gtest_filter='*SortInvariantWide*:WideBvhRender.*:EmbreeHits.*:BvhWide*' ) > $OUT/invariant.log 2>&1
( time timeout 330 $B/raylab bench --cases temple@hall,.dev/sponza/Sponza.gltf@CameraMain,clutter:1000000@overview \
  --strategies two-point --sort-policies always,auto --bvhs binary,wide --trace-shades split,fused \
  --sizes 2048x1024,4096x2048 --bounces 4 --timed-frames 12 --warmup 4 --reference-spp 4 --no-detail --no-charts \
  --out-dir /tmp/heart ) > $OUT/bench.log 2>&1
cp /tmp/heart/results.csv $OUT/heart.csv; cp /tmp/heart/results.jsonl $OUT/heart.jsonl
echo done
