#!/usr/bin/env bash
# One device call (about 6 minutes). Binaries in .dev/bins.tar.xz: build-device/raylab (this revision: sortbench
# times its sorts back to back after half a second of warm-up; the pair traversal's slabs as a precise fma),
# .dev/old/raylab (fe2275f: one sort a submission, the host's check between sizes) and .dev/t2/raylab (this
# revision with Tuning::radixTilesPerGroup = 2 as the default, so the frame sorts with it).
# Part 1: the radix "cliff" (radix-tile-size, results.md "GPU sorts alone"): old against new sortbench, the same
# counts from 1M to 8.4M, 23-bit keys, uniform and few-valued, every dispatch timed. Part 2: --radix-tiles 1, 2, 4
# with the new sortbench. Part 3: the frame with 2 tiles a group against 1 (benchBinaries, 4 bounces, two-point,
# radix, split; 720p and 4096x2048; two interleaved rounds). Part 4: the trace before and after the precise fma
# (tracebench, Sponza and the hall, 2048x1024, interleaved). Part 5: the GPU tests that failed on the H100 at
# fe2275f (the pair traversal's twin, the heatmap product run in one process).
source docs/results/device-unpack.sh
t0=$SECONDS
N=1048576,2097152,3145728,4194304,5242880,6291456,8388608
for round in 1 2; do
  for bin in old new; do
    B=build-device/raylab; [ $bin = old ] && B=.dev/old/raylab
    for dist in uniform few; do
      timeout 90 $B sortbench --n $N --bits 23 --dist $dist --sort radix --repeat 20 --csv /tmp/sb.csv \
        --steps /tmp/st.csv > /dev/null 2>&1 || echo "sortbench $bin $dist exit $?" >> $OUT/errors.txt
      appendRows /tmp/sb.csv $OUT/knee.csv binary,round,dist $bin,$round,$dist
      appendRows /tmp/st.csv $OUT/knee-steps.csv binary,round,dist $bin,$round,$dist
    done
  done
done
echo "knee: $((SECONDS - t0)) s"; t0=$SECONDS
for dist in uniform few; do
  for tiles in 1 2 4 1 2 4; do
    timeout 60 build-device/raylab sortbench --n 921600,2097152,8388608 --bits 23 --dist $dist --sort radix \
      --radix-tiles $tiles --repeat 20 --csv /tmp/sb.csv > /dev/null 2>&1 || echo "tiles $dist $tiles exit $?" >> $OUT/errors.txt
    appendRows /tmp/sb.csv $OUT/tiles.csv dist,tiles $dist,$tiles
  done
done
echo "tiles: $((SECONDS - t0)) s"; t0=$SECONDS
benchBinaries frame.csv "$S@CameraMain,temple@hall,clutter:1000000" 720p,4096x2048 150 \
  t1=build-device/raylab t2=.dev/t2/raylab
echo "frame: $((SECONDS - t0)) s"; t0=$SECONDS
for round in 1 2; do
  for bin in old new; do
    B=build-device/raylab; [ $bin = old ] && B=.dev/old/raylab
    for c in "$S@CameraMain" temple@hall; do
      timeout 40 $B tracebench --scene "${c%@*}" --view ${c#*@} --size 2048x1024 --bvhs binary,sbvh --repeat 20 \
        --csv /tmp/tb.csv > /dev/null 2>&1 || echo "tracebench $bin $c exit $?" >> $OUT/errors.txt
      appendRows /tmp/tb.csv $OUT/tracebench.csv binary,round,case $bin,$round,$(basename ${c%@*})
    done
  done
done
echo "tracebench: $((SECONDS - t0)) s"; t0=$SECONDS
RAYLAB_VALIDATE=1 timeout 120 build-device/tests/raylab_gpu_tests --gtest_filter='EmbreeHits.*:HeatmapProduct.*:ValidationChecks.*' \
  > $OUT/gpu-tests.log 2>&1; echo "exit $?" >> $OUT/gpu-tests.log
echo "tests: $((SECONDS - t0)) s"
