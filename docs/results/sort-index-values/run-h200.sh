#!/usr/bin/env bash
# For a session with the device (about 4 minutes): the sort making its own values (SortValues::Indices: the keys
# stage writes no payload, the first radix pass reads none; .dev/indices/raylab) against the build before it
# (build-device/raylab, 7e508fc: the keys stage writes slot i, every pass reads it), in the frame at real-time and
# study sizes, 4 bounces, two-point keys, radix; binaries interleaved, two rounds each. What to read: the `keys`
# and `sort` stage columns (8 bytes a live path less per sorted bounce between them) and the frame.
source docs/results/device-unpack.sh
CASES="$S@CameraMain,temple@hall,clutter:1000000"
t0=$SECONDS
for round in 1 2; do
  for v in given indices; do
    bin=build-device/raylab; [ $v = indices ] && bin=.dev/indices/raylab
    timeout 140 $bin bench --cases "$CASES" --sizes 720p,1080p,4096x2048 --bounces 4 --strategies two-point \
      --sorts radix --trace-shades split --rounds 1 --no-detail --no-charts --out-dir /tmp/v-$v-$round \
      > /tmp/v-$v-$round.log 2>&1 || echo "bench $v $round exit $?" >> $OUT/errors.txt
    appendRows /tmp/v-$v-$round/results.csv $OUT/values.csv binary,round $v,$round
  done
done
echo "benches: $((SECONDS - t0)) s" >> $OUT/times.txt
echo done
