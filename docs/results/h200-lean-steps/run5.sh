#!/usr/bin/env bash
# Issue 35's sorting study over the lean trace (8007d98) with 8 bounces: run4.sh's second part, --bounces 8.
source docs/results/device-unpack.sh
B=build-device/raylab
t0=$SECONDS
timeout 250 $B bench \
  --cases "$S@CameraMain,temple@hall,temple@openings,temple-detail:1000000@hall,clutter:1000000" \
  --sizes 2048x1024,4096x2048 --bounces 8 --strategies two-point --trace-shades split,fused --rounds 2 \
  --reference-spp 4 --no-detail --no-charts --out-dir /tmp/bench8 > /tmp/bench8.log 2>&1 \
  || echo "study bench exit $?" >> $OUT/errors.txt
cp /tmp/bench8/results.csv $OUT/study-8.csv 2>/dev/null
tail -c 100000 /tmp/bench8.log | xz > $OUT/study-8.log.xz
echo "study 8: $((SECONDS - t0)) s" >> $OUT/times.txt
echo done
