#!/usr/bin/env bash
# The invariant on the device at this revision (the radix passes' rotation, tiles a group as a specialization
# constant and presplit 0.001 as the default changed sort shaders and the tree since the last GPU run of it):
# part 1 the GPU tests of sorting and the invariant (raylab_gpu_tests; they need the validation layer, so
# .dev/carry/gl holds Debian 12's vulkan-validationlayers package); part 2 the
# command line: every key strategy, sort and tree renders the unsorted image's PNG byte for byte on the temple's
# hall and Sponza, split and fused, with the detailed statistics on. Carry .dev/bins.tar.xz (with
# build-device/tests/raylab_gpu_tests) and build-device/lib/libembree3.so.3.xz.
source docs/results/device-unpack.sh
R=build-device/raylab
( time RAYLAB_VALIDATE=1 timeout 200 build-device/tests/raylab_gpu_tests --gtest_filter='SortInvariant*:*GpuSort*:*Invariant*:*SortPolicy*' \
    --gtest_brief=1 ) > $OUT/gpu-tests.log 2>&1
echo "gpu tests exit $?" >> $OUT/gpu-tests.log
t0=$SECONDS
for bvh in sbvh binary wide; do for c in temple@hall $S@CameraMain; do
  scene=${c%@*}; view=${c#*@}
  base="$R render --scene $scene --view $view --size 1024x512 --bounces 4 --frames 3 --bvh $bvh"
  $base --out /tmp/u.png > /dev/null 2>&1 || echo "FAIL unsorted $bvh $c"
  for st in dead-last fixed average ema gaussian origin direction origin-direction two-point oracle; do
    $base --strategy $st --stats /tmp/s.json --out /tmp/s.png > /dev/null 2>&1 || echo "FAIL render $bvh $c $st"
    cmp -s /tmp/u.png /tmp/s.png && echo "same $bvh $(basename $scene) $st" || echo "DIFFERENT $bvh $(basename $scene) $st"
  done
  for sort in onesweep bitonic tile; do
    $base --strategy two-point --sort $sort --out /tmp/s.png > /dev/null 2>&1 || echo "FAIL render $bvh $c $sort"
    cmp -s /tmp/u.png /tmp/s.png && echo "same $bvh $(basename $scene) two-point $sort" || echo "DIFFERENT $bvh $(basename $scene) two-point $sort"
  done
  for pair in "--trace-shade fused|--sort-policy auto" "--trace-shade loop|" "--compaction shade|--sort-bits 16"; do
    both=${pair%|*} sorted=${pair#*|}
    $base $both --out /tmp/ue.png > /dev/null 2>&1 || echo "FAIL unsorted $bvh $c $both"
    $base $both --strategy two-point $sorted --out /tmp/s.png > /dev/null 2>&1 || echo "FAIL render $bvh $c $both $sorted"
    cmp -s /tmp/ue.png /tmp/s.png && echo "same $bvh $(basename $scene) two-point $both $sorted" || echo "DIFFERENT $bvh $(basename $scene) two-point $both $sorted"
  done
done; done > $OUT/invariant-cli.log 2>&1
echo "cli: $((SECONDS - t0)) s" >> $OUT/invariant-cli.log
