#!/usr/bin/env bash
# Device call B (issue 36), about 6 minutes: OneSweep against radix in the frame at real-time and study sizes, and
# the bounce loop holding one traversal (loop_layout.py applied: .dev/loop/raylab) against this binary's.
# Device: source docs/results/device-unpack.sh (as the earlier run*.sh). Local check: LOCAL=1 OUT=/tmp/x bash this.
if [ -n "${LOCAL:-}" ]; then
  B=build/raylab; S=/work/shared/scenes/Sponza/Sponza.gltf; mkdir -p $OUT
  SIZE2=128x64; SIZE4=256x128; SIZES36=128x64,160x96; REP=2; CASES36="temple@hall,clutter:50000"
  LOOP=${LOOPBIN:-}; SIZE_RT=64x32; CASES_RT="temple@hall,temple@alley"
else
  source docs/results/device-unpack.sh
  B=build-device/raylab
  SIZE2=2048x1024; SIZE4=4096x2048; SIZES36=720p,1080p,2048x1024,4096x2048; REP=20
  CASES36="$S@CameraMain,temple@hall,temple-detail:1000000@hall,clutter:1000000"
  LOOP=.dev/loop/raylab; SIZE_RT=512x256; CASES_RT="$S@CameraMain,temple@hall,temple@alley,temple@openings,clutter:1000000"
fi
# 2. Issue 36: radix against OneSweep in the frame, real-time sizes and the study's, 4 bounces, two-point keys.
t1=$SECONDS
timeout 300 $B bench --cases "$CASES36" --sizes $SIZES36 --bounces 4 --strategies two-point --sorts radix,onesweep \
  --trace-shades split --rounds 3 --no-detail --no-charts --out-dir /tmp/b36 > /tmp/b36.log 2>&1 \
  || echo "bench 36 exit $?" >> $OUT/errors.txt
cp /tmp/b36/results.csv $OUT/onesweep.csv 2>/dev/null
tail -c 100000 /tmp/b36.log | xz > $OUT/onesweep.log.xz
echo "bench 36: $((SECONDS - t1)) s" >> $OUT/times.txt
# 3. Issue 36 at 512x256: the bounce loop holding one traversal (loop_layout.py applied: $LOOP) against this
# binary's loop and the megakernel, unsorted, 3 rounds interleaved between the binaries.
t2=$SECONDS
if [ -n "$LOOP" ] && [ -x "$LOOP" ]; then
  for r in 1 2 3; do
    for v in base loop; do
      bin=$B; [ $v = loop ] && bin=$LOOP
      timeout 90 $bin bench --cases "$CASES_RT" --sizes $SIZE_RT --bounces 4 --strategies none --trace-shades loop \
        --rounds 1 --timed-frames 8 --no-detail --no-charts --out-dir /tmp/loop-$v-$r > /tmp/loop-$v-$r.log 2>&1 \
        || echo "loop $v round $r exit $?" >> $OUT/errors.txt
      [ -s $OUT/loop.csv ] || head -1 /tmp/loop-$v-$r/results.csv | sed 's/^/variant,round,/' > $OUT/loop.csv
      tail -n +2 /tmp/loop-$v-$r/results.csv | sed "s/^/$v,$r,/" >> $OUT/loop.csv
    done
  done
fi
echo "loop A/B: $((SECONDS - t2)) s" >> $OUT/times.txt
echo done
