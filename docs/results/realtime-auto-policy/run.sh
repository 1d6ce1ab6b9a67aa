#!/usr/bin/env bash
# Issue 36: does the auto sort policy keep the sorted wavefront from losing at real-time sizes, where always
# sorting loses on the scenes we keep (../presplit-default-study)? The real-time table's bench with
# --sort-policies always,auto (auto is timed once its plan stops exploring), split trace and shade, two rounds.
# The packed binary is 7e508fc; --bvh-presplit 0.001 makes its frame main's.
source docs/results/device-unpack.sh
B=build-device/raylab
t0=$SECONDS
timeout 400 $B bench --bvh-presplit 0.001 --cases temple@hall,temple@openings,$S@CameraMain,clutter:1000000 \
  --strategies two-point --sort-policies always,auto --sizes 512x256,720p,1080p --bounces 4 --trace-shades split \
  --rounds 2 --timed-frames 6 --warmup 2 --reference-spp 4 --no-detail --no-charts --out-dir /tmp/rt > /tmp/rt.log 2>&1 \
  || echo "realtime auto bench exit $?" >> $OUT/errors.txt
cp /tmp/rt/results.csv $OUT/auto.csv 2>/dev/null
tail -c 60000 /tmp/rt.log | xz > $OUT/log.xz
echo "auto: $((SECONDS - t0)) s" >> $OUT/times.txt
echo done
