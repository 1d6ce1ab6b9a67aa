#!/usr/bin/env bash
# Issue 20's sorting tables on lavapipe: binary against wide BVH under sorting, 512x256, 4 and 8 bounces.
# Usage: bash docs/results/lavapipe-wide-bvh/run.sh RAYLAB OUT_DIR   (from the repository root)
R=${1:-build/raylab}; OUT=${2:-lavapipe-wide-bvh}
S=../shared/scenes/Sponza/Sponza.gltf
[ -f $S ] || S=/src/shared/scenes/Sponza/Sponza.gltf  # inside .ci/debian13's root
time $R bench --cases temple@hall,temple@alley,temple@openings,$S@CameraMain,temple-detail:1000000@hall \
  --strategies two-point --sort-policies always,auto --bvhs binary,wide --trace-shades split,fused \
  --size 512x256 --bounces 4,8 --timed-frames 6 --warmup 4 --reference-spp 1 --no-detail --no-charts --out-dir $OUT
