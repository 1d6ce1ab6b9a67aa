#!/usr/bin/env bash
# Issue 35, third step, one device call. (1) Does the wide traversal's code beside the binary one cost the binary
# trace registers? .dev/hack/raylab is b207ee7 with traverseSceneBvh calling the binary traversal only (no
# uniform branch to the wide one, so one traversal in each pipeline); build-device/raylab is b207ee7. The trace
# stage's rays per second as in run.sh (Sponza CameraMain, 2 bounces, unsorted, split, no compaction), sbvh,
# 2048x1024 and 4096x2048, three interleaved rounds. (2) Which layout is fastest: the bench over sbvh and wide
# (Sponza, the hall, the clutter room; 1920x1080 and 4096x2048; 4 bounces; unsorted, two-point; 3 rounds).
source docs/results/device-unpack.sh  # also sets S (Sponza), makes /tmp/out, writes $OUT/gpu.txt
for round in 1 2 3; do
  for bin in new hack; do
    B=$([ $bin = new ] && echo build-device/raylab || echo .dev/hack/raylab)
    for size in 2048x1024 4096x2048; do
      $B render --scene $S --view CameraMain --size $size --bounces 2 --strategy none --compaction none \
        --trace-shade split --bvh sbvh --frames 12 --stats /tmp/out/trace-$bin-sbvh-$size-r$round.json \
        --detail-every 0 --out /tmp/x.png > /dev/null 2>&1 || echo "failed: $bin $size" >> $OUT/errors.txt
    done
  done
done
tar -cJf $OUT/trace2.tar.xz -C /tmp out
timeout 400 build-device/raylab bench --cases "$S@CameraMain,temple@hall,clutter:1000000" --sizes 1920x1080,4096x2048 \
  --bounces 4 --bvhs sbvh,wide --strategies two-point --rounds 3 --no-charts \
  --no-detail --out-dir /tmp/bench > $OUT/bench2.log 2>&1 || echo "bench exit $?" >> $OUT/errors.txt
cp /tmp/bench/results.csv $OUT/bench2.csv
echo done
