#!/usr/bin/env bash
# Issue 35's lavapipe check at the presplit default (h200-traversal's lavapipe/ did it before presplit 0.001 became
# the default): on this Debian 12 machine (build/, lavapipe, Mesa 22.3.6) and in the Debian 13 root of .ci/debian13
# (Mesa 25), the same renders of the hall and Sponza at 512x256 on all three trees, compared as PNGs across the two
# systems, and the bench's ratios of each tree over sbvh. Usage: bash docs/results/lavapipe-presplit-default/run.sh
# OUT_DIR SYSTEM, where SYSTEM is d12 (runs here, with build/raylab) or d13 (run inside the root by
# `bash .ci/debian13 "bash docs/results/lavapipe-presplit-default/run.sh /tmp/d13 d13"`, building /var/raylab/build).
set -euo pipefail
out=$1 system=$2
if [ "$system" = d13 ]; then
  BUILD_DIR=/var/raylab/build bash .ci/setup > /tmp/d13-build.log 2>&1
  B=/var/raylab/build/raylab S=/src/shared/scenes/Sponza/Sponza.gltf
else
  B=build/raylab S=../shared/scenes/Sponza/Sponza.gltf
fi
mkdir -p "$out"
for bvh in binary sbvh wide; do
  $B render --scene temple --view hall --size 512x256 --frames 4 --bvh $bvh --out "$out/hall-$bvh.png" > /dev/null
  $B render --scene "$S" --view CameraMain --size 512x256 --frames 4 --bvh $bvh --out "$out/sponza-$bvh.png" > /dev/null
done
$B bench --cases "$S@CameraMain,temple@hall" --sizes 512x256 --bounces 4 --bvhs binary,sbvh,wide --strategies two-point \
  --rounds 2 --timed-frames 4 --warmup 1 --reference-spp 4 --no-detail --no-charts --out-dir "$out/bench" > "$out/bench.log" 2>&1
echo "$system done"
