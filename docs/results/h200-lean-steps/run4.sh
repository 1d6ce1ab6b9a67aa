#!/usr/bin/env bash
# One device call, three parts, at 8007d98 (the lean traversal with the spatial-split tree's new weights):
# 1. The tree's weights together: `new` (8007d98: intersection cost 1.5, leaves of at most 4) against run3.sh's
#    environment-reading build of 4ad3790 as `base` (1.0 and 8) and `ic15` (1.5 and 8); trace rates as in
#    run.sh, the megakernel on Sponza and the clutter room; two interleaved rounds (combo.tar.xz).
# 2. Issue 35's sorting study again over this trace, 4 bounces (h200-traversal/study.sh with two rounds).
# 3. Issue 36's real-time table again (h200-realtime-one-traversal/run.sh).
source docs/results/device-unpack.sh
B=build-device/raylab
t0=$SECONDS
run() {  # name config size megakernel-too scene args...
  local name=$1 cfg=$2 size=$3 mk=$4; shift 4
  local pre=""
  case $cfg in new) exe=$B;; base) exe=.dev/ic/raylab;; ic15) exe=.dev/ic/raylab; pre="RL_IC=1.5";; esac
  env $pre $exe render "$@" --size $size --bounces 2 --strategy none --compaction none \
    --trace-shade split --frames 10 --stats /tmp/out/$name-$cfg-sbvh-$size-r$round.json --detail-every 0 \
    --out /tmp/x.png > /dev/null 2>&1 || echo "failed: $name $cfg $size" >> $OUT/errors.txt
  [ $mk = mk ] || return 0
  env $pre $exe render "$@" --size $size --bounces 4 --kernel megakernel --frames 10 \
    --stats /tmp/mk/$name-$cfg-sbvh-$size-r$round.json --detail-every 0 --out /tmp/x.png \
    > /dev/null 2>&1 || echo "failed: mk $name $cfg $size" >> $OUT/errors.txt
}
mkdir -p /tmp/mk
for round in 1 2; do
  for cfg in base ic15 new; do
    run sponza $cfg 2048x1024 mk --scene $S --view CameraMain
    run sponza $cfg 4096x2048 - --scene $S --view CameraMain
    run hall $cfg 2048x1024 - --scene temple --view hall
    run clutter $cfg 2048x1024 mk --scene clutter:1000000
  done
done
tar -cJf $OUT/combo.tar.xz -C /tmp out mk
echo "combo: $((SECONDS - t0)) s" >> $OUT/times.txt; t0=$SECONDS
timeout 290 $B bench \
  --cases "$S@CameraMain,temple@hall,temple@openings,temple-detail:1000000@hall,clutter:1000000" \
  --sizes 2048x1024,4096x2048 --bounces 4 --strategies two-point --trace-shades split,fused --rounds 2 \
  --reference-spp 4 --no-detail --no-charts --out-dir /tmp/bench4 > /tmp/bench4.log 2>&1 \
  || echo "study bench exit $?" >> $OUT/errors.txt
cp /tmp/bench4/results.csv $OUT/study-4.csv 2>/dev/null
tail -c 100000 /tmp/bench4.log | xz > $OUT/study-4.log.xz
echo "study: $((SECONDS - t0)) s" >> $OUT/times.txt; t0=$SECONDS
timeout 150 $B bench --cases temple@alley,temple@hall,temple@openings,$S@CameraMain,clutter:1000000 \
  --strategies two-point --sizes 512x256,720p,1080p --bounces 4 --trace-shades split,loop \
  --rounds 2 --timed-frames 6 --warmup 2 --reference-spp 4 --no-charts --out-dir /tmp/rt > /tmp/rt.log 2>&1 \
  || echo "realtime bench exit $?" >> $OUT/errors.txt
cp /tmp/rt/results.csv $OUT/realtime.csv 2>/dev/null
tail -c 100000 /tmp/rt.log | xz > $OUT/realtime.log.xz
echo "realtime: $((SECONDS - t0)) s" >> $OUT/times.txt
echo done
