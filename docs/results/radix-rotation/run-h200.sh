#!/usr/bin/env bash
# For a session with the device (about 4 minutes): the radix sort's three passes through a second scratch set
# (7b190ea, build-device/raylab) against the copy back before it (.dev/copyback/raylab: the same tree with d387578's
# renderer/reorder/gpu_sort.{h,cpp}, so its revision column reads the same; .dev/bins.tar.xz holds both), in the
# frame at real-time and study sizes, 4 bounces, two-point keys, radix; binaries interleaved, two rounds each.
# Keys + sort against the bandwidth floor: the `keys` and `sort` stage columns at 4096x2048.
source docs/results/device-unpack.sh
B=build-device/raylab
CASES="$S@CameraMain,temple@hall,temple-detail:1000000@hall,clutter:1000000"
t0=$SECONDS
benchBinaries rotation.csv "$CASES" 720p,1080p,4096x2048 150 rotate=$B copyback=.dev/copyback/raylab
echo "rotation: $((SECONDS - t0)) s" >> $OUT/times.txt
# 2. Issue 36: is the gather fused into the trace (the default, measured at 2.1M paths and more) still the better
# choice at real-time sizes, where the sorted trace gained nothing on Sponza? Fusion none against gather.
t1=$SECONDS
if [ $((t1 - t0)) -lt 400 ]; then
  timeout 150 $B bench --cases "$S@CameraMain,temple@hall" --sizes 720p,1080p --bounces 4 --strategies two-point     --sorts radix --fusions none,gather --trace-shades split --rounds 2 --no-detail --no-charts --out-dir /tmp/fu     > /tmp/fu.log 2>&1 || echo "bench fusion exit $?" >> $OUT/errors.txt
  cp /tmp/fu/results.csv $OUT/fusion.csv 2>/dev/null
fi
echo "fusion: $((SECONDS - t1)) s" >> $OUT/times.txt
echo done
