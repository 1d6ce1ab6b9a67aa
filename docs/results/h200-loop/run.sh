#!/usr/bin/env bash
# Issue 36 (the wavefront at real-time sizes) and issue 37 (the caches' resets per path frame) on the H200, one
# device call. Packing as in ../h200-true-figures/run.sh (.dev/bins.tar.xz with build-device/raylab, Sponza and
# the loader's packages; carry it and build-device/lib/libembree3.so.3.xz).
# 1. The bench over the temple's three views, Sponza and the clutter room at 1e6 triangles at 512x256, 720p,
#    1080p and 2048x1024, 4 bounces: the megakernel, the unsorted wavefront and two-point sorted, each with
#    trace and shade split, fused and loop (--trace-shade loop: the bounces after the last sort in one
#    dispatch); 2 interleaved rounds.
# 2. Sponza's cut path (../h200-motion/sponza_cut.json) at 2048x1024, gaussian under always with reset
#    thresholds 5, 20 and inf: path_frames.jsonl now carries each frame's length_cache_resets.
source docs/results/device-unpack.sh  # also sets S (Sponza), makes /tmp/out, writes $OUT/gpu.txt
B=build-device/raylab
start=$(date +%s)
timeout 360 $B bench --cases temple@alley,temple@hall,temple@openings,$S@CameraMain,clutter:1000000 \
  --strategies two-point --sizes 512x256,720p,1080p,2048x1024 --bounces 4 --trace-shades split,fused,loop \
  --rounds 2 --timed-frames 6 --warmup 2 --reference-spp 4 --out-dir /tmp/loop > $OUT/bench.log 2>&1
echo "bench: exit $?, $(( $(date +%s) - start )) s" >> $OUT/times.txt
cp /tmp/loop/results.csv $OUT/results.csv
tar -cJf $OUT/bench.tar.xz -C /tmp loop
start=$(date +%s)
timeout 100 $B bench --cases $S --camera-path docs/results/h200-motion/sponza_cut.json --sizes 2048x1024 \
  --bounces 4 --rounds 1 --warmup 4 --strategies gaussian --sort-policies always --gauss-resets 5,20,inf \
  --out-dir /tmp/resets > $OUT/resets.log 2>&1
echo "resets: exit $?, $(( $(date +%s) - start )) s" >> $OUT/times.txt
tar -cJf $OUT/resets.tar.xz -C /tmp resets
echo done
