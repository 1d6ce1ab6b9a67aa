#!/usr/bin/env bash
# Issue 35's sorting study and issue 36's real-time table at the presplit default (97d7baf). The packed binary is
# 7e508fc (the same frame code; its presplit default was 0), so every bench passes --bvh-presplit 0.001: the frame
# main renders since 97d7baf. Part 1: the study, 4 bounces, 2.1M and 8.4M paths, five cases, split and fused, two
# rounds (h200-lean-steps/run4.sh's command); part 2: the real-time table, 720p and 1080p, split and loop.
source docs/results/device-unpack.sh
B=build-device/raylab
t0=$SECONDS
timeout 280 $B bench --bvh-presplit 0.001 \
  --cases "$S@CameraMain,temple@hall,temple@openings,temple-detail:1000000@hall,clutter:1000000" \
  --sizes 2048x1024,4096x2048 --bounces 4 --strategies two-point --trace-shades split,fused --rounds 2 \
  --reference-spp 4 --no-detail --no-charts --out-dir /tmp/bench4 > /tmp/bench4.log 2>&1 \
  || echo "study bench exit $?" >> $OUT/errors.txt
cp /tmp/bench4/results.csv $OUT/study-4.csv 2>/dev/null
echo "study: $((SECONDS - t0)) s" >> $OUT/times.txt; t0=$SECONDS
timeout 170 $B bench --bvh-presplit 0.001 --cases temple@hall,temple@openings,$S@CameraMain,clutter:1000000 \
  --strategies two-point --sizes 512x256,720p,1080p --bounces 4 --trace-shades split,loop \
  --rounds 2 --timed-frames 6 --warmup 2 --reference-spp 4 --no-detail --no-charts --out-dir /tmp/rt > /tmp/rt.log 2>&1 \
  || echo "realtime bench exit $?" >> $OUT/errors.txt
cp /tmp/rt/results.csv $OUT/realtime.csv 2>/dev/null
tail -c 60000 /tmp/bench4.log /tmp/rt.log | xz > $OUT/logs.xz
echo "realtime: $((SECONDS - t0)) s" >> $OUT/times.txt
echo done
# The 8-bounce study ran in the next call on the same warm machine, this command after sourcing device-unpack.sh:
#   timeout 280 $B bench --bvh-presplit 0.001 --cases "$S@CameraMain,temple@hall,temple@openings,\
#     temple-detail:1000000@hall,clutter:1000000" --sizes 2048x1024,4096x2048 --bounces 8 --strategies two-point \
#     --trace-shades split,fused --rounds 2 --reference-spp 4 --no-detail --no-charts --out-dir /tmp/bench8
#   (results.csv is study-8.csv)
