#!/usr/bin/env bash
# Issue 36 on the H200, one device call (about 5 minutes of GPU time, at most 6 with the timeouts): the
# frame's fixed costs at real-time sizes. One bench over the built-in temple's three views at 512x256, 720p
# (1280x720), 1080p (1920x1080), 2048x1024 and 4096x2048, 4 bounces: the megakernel, the unsorted wavefront
# in its variants (compaction shade and none, trace and shade split and fused: the best of them is "best
# unsorted") and two-point sorted in the same variants; 2 interleaved rounds. Its CSV carries, per cell,
# dispatches, barriers, size_writes, submissions and fixed_cost_ms (dispatches x the run's empty dispatch,
# an estimate), and the bench prints empty_dispatch_us. Then one `render --stats` of two-point at 720p for
# the per-stage command counts. Carry as docs/results/h200-true-figures/run.sh says (the same packing:
# .dev/bins.tar.xz with build-device/raylab, .dev/carry/gl); where a raylab is already built, RAYLAB=path
# uses it and the unpacking is skipped. At most 8 files into $OUT:
#   gpu.txt, bench.log, results.csv, bench.tar.xz (the whole bench folder: JSONL, cells, charts),
#   stats-720p.json, render.log, times.txt
set -u
if [ -z "${RAYLAB:-}" ]; then
  tar -xJf .dev/bins.tar.xz
  for f in .dev/carry/gl/*.deb; do dpkg -x $f /; done; ldconfig
  xz -dkf build-device/lib/*.xz
fi
B=${RAYLAB:-build-device/raylab}
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv > $OUT/gpu.txt 2>&1
start=$(date +%s)
# The bench: 3 views x 5 sizes x 8 cells x 2 rounds. Warm-up is at least half a second a cell, which is most of
# the small sizes' time; the reference image is only for final_rel_mse (4 spp is enough to check it).
timeout 330 $B bench --cases temple@alley,temple@hall,temple@openings --strategies two-point \
  --sizes 512x256,720p,1080p,2048x1024,4096x2048 --bounces 4 \
  --compactions none,shade --trace-shades split,fused \
  --rounds 2 --timed-frames 6 --warmup 2 --reference-spp 4 --out-dir /tmp/fixed-costs > $OUT/bench.log 2>&1
echo "bench: exit $?, $(( $(date +%s) - start )) s" >> $OUT/times.txt
cp /tmp/fixed-costs/results.csv $OUT/results.csv 2>/dev/null
tar -cJf $OUT/bench.tar.xz -C /tmp fixed-costs
# Per stage: which stage issues how many dispatches and barriers in a sorted frame at 720p (the stats' "commands").
start=$(date +%s)
timeout 20 $B render --scene temple --view hall --size 720p --bounces 4 --frames 4 --strategy two-point \
  --stats $OUT/stats-720p.json --out /tmp/x.png > $OUT/render.log 2>&1
echo "render: exit $?, $(( $(date +%s) - start )) s" >> $OUT/times.txt
echo done
