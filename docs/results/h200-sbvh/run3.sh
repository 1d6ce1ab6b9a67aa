#!/usr/bin/env bash
# Issue 35, leaf size of the spatial-split tree, one device call: build-device/raylab is 738b19f (at most 8
# triangles a leaf, Embree's SAH with both costs 1); .dev/leaf4 and .dev/leaf16 the same with at most 4 and 16.
# The trace stage's rays per second (as run.sh: 2 bounces, unsorted, split, no compaction) on Sponza CameraMain
# and the temple's hall, 2048x1024 and 4096x2048, and the whole 4-bounce frame unsorted and two-point at
# 4096x2048 (12 frames, 2 on kept); three interleaved rounds.
source docs/results/device-unpack.sh  # also sets S (Sponza), makes /tmp/out, writes $OUT/gpu.txt
for round in 1 2 3; do
  for bin in new leaf4 leaf16; do
    B=$([ $bin = new ] && echo build-device/raylab || echo .dev/$bin/raylab)
    for scene in sponza hall; do
      args=$([ $scene = sponza ] && echo "--scene $S --view CameraMain" || echo "--scene temple --view hall")
      for size in 2048x1024 4096x2048; do
        $B render $args --size $size --bounces 2 --strategy none --compaction none --trace-shade split --frames 12 \
          --stats /tmp/out/trace-$bin-$scene-$size-r$round.json --detail-every 0 --out /tmp/x.png > /dev/null 2>&1 \
          || echo "failed: $bin $scene $size" >> $OUT/errors.txt
      done
      for strategy in none two-point; do
        $B render $args --size 4096x2048 --bounces 4 --strategy $strategy --frames 12 \
          --stats /tmp/out/$strategy-$bin-$scene-4096x2048-r$round.json --detail-every 0 --out /tmp/x.png \
          > /dev/null 2>&1 || echo "failed: $bin $scene $strategy" >> $OUT/errors.txt
      done
    done
  done
done
B=build-device/raylab
for bin in new leaf4 leaf16; do
  B=$([ $bin = new ] && echo build-device/raylab || echo .dev/$bin/raylab)
  $B render --scene $S --view CameraMain --size 64x32 --stats /tmp/out/facts-$bin.json --out /tmp/x.png > /dev/null 2>&1
done
tar -cJf $OUT/trace3.tar.xz -C /tmp out
echo done
