#!/usr/bin/env bash
# The bounce loop's ray counts: in the loop (loop1: a subgroup sum and an atomic per bounce, inside divergent
# code, as measured by run.sh) or after it (loop2: each lane counts the bounces it traced once the subgroup has
# reconverged, as the megakernel does). Two binaries, two interleaved rounds of one bench each: Sponza, the
# alley and the hall at 512x256 and 2048x1024, 4 bounces, --trace-shades loop (megakernel and unsorted rows).
source docs/results/device-unpack.sh
for round in 1 2; do
  for bin in loop1 loop2; do
    timeout 100 .dev/$bin/raylab bench --cases temple@alley,temple@hall,$S@CameraMain --strategies two-point \
      --sizes 512x256,2048x1024 --bounces 4 --trace-shades loop --rounds 1 --timed-frames 6 --warmup 2 \
      --reference-spp 1 --out-dir /tmp/$bin-r$round > /tmp/$bin-r$round.log 2>&1
    echo "$bin round $round: exit $?" >> $OUT/times.txt
    cp /tmp/$bin-r$round/results.csv $OUT/$bin-r$round.csv
  done
done
echo done
