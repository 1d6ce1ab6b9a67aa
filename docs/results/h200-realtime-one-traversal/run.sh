#!/usr/bin/env bash
# Issue 36's real-time table again after the megakernel came to hold one traversal (31a0ace: 80 -> 72
# registers, docs/results/h200-binary-only), one device call. Packing as in ../h200-true-figures/run.sh.
# The bench over the temple's three views, Sponza and the clutter room at 1e6 triangles at 512x256, 720p and
# 1080p, 4 bounces: the megakernel, the unsorted wavefront and two-point sorted, each with trace and shade
# split and as the bounce loop; 2 interleaved rounds. (h200-loop ran the same bench at 0ffff2f, with fused
# stages and 2048x1024 too.)
source docs/results/device-unpack.sh  # also sets S (Sponza), makes /tmp/out, writes $OUT/gpu.txt
B=build-device/raylab
start=$(date +%s)
timeout 185 $B bench --cases temple@alley,temple@hall,temple@openings,$S@CameraMain,clutter:1000000 \
  --strategies two-point --sizes 512x256,720p,1080p --bounces 4 --trace-shades split,loop \
  --rounds 2 --timed-frames 6 --warmup 2 --reference-spp 4 --out-dir /tmp/rt > $OUT/bench.log 2>&1
echo "bench: exit $?, $(( $(date +%s) - start )) s" >> $OUT/times.txt
cp /tmp/rt/results.csv $OUT/results.csv
echo done
