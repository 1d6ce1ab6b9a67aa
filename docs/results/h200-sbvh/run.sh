#!/usr/bin/env bash
# Issue 35, second step, one device call. (1) The trace stage's rays per second per bounce from `render --stats`:
# the binary tree before this change (.dev/old/raylab, 70a838f's parent tree: pair nodes, scanline camera rays)
# against this revision's binary tree, its spatial-split tree (sbvh) and the wide tree, unsorted, Sponza
# CameraMain, 2 bounces (camera rays, first bounce), no compaction, split trace and shade (the command),
# 2048x1024 and 4096x2048, 12 frames each (frames 2 on kept); three interleaved rounds. (2) The answer again over
# the faster trace: the bench's sorted and unsorted frames on Sponza, the hall and the clutter room at 1920x1080
# and 4096x2048, 4 bounces, binary and sbvh, split and fused trace+shade, 3 rounds.
# Carry .dev/bins.tar.xz (build-device/raylab: new; .dev/old/raylab: before; Sponza; the loader) and the
# Embree library, as h200-true-figures/run.sh says.
source docs/results/device-unpack.sh  # also sets S (Sponza), makes /tmp/out, writes $OUT/gpu.txt
for round in 1 2 3; do
  for bin in old new; do
    B=$([ $bin = new ] && echo build-device/raylab || echo .dev/old/raylab)
    bvhs=$([ $bin = new ] && echo "binary sbvh wide" || echo "binary wide")
    for size in 2048x1024 4096x2048; do
      for bvh in $bvhs; do
        $B render --scene $S --view CameraMain --size $size --bounces 2 --strategy none --compaction none \
          --trace-shade split --bvh $bvh --frames 12 --stats /tmp/out/trace-$bin-$bvh-$size-r$round.json \
          --detail-every 0 --out /tmp/x.png > /dev/null 2>&1 || echo "failed: $bin $bvh $size" >> $OUT/errors.txt
      done
    done
  done
done
build-device/raylab render --scene $S --view CameraMain --size 64x32 --bvh sbvh --stats /tmp/out/facts-sbvh.json \
  --out /tmp/x.png > /dev/null 2>&1
tar -cJf $OUT/trace.tar.xz -C /tmp out
timeout 400 build-device/raylab bench --cases "$S@CameraMain,temple@hall,clutter:1000000" --sizes 1920x1080,4096x2048 \
  --bounces 4 --bvhs binary,sbvh --strategies two-point --trace-shades split,fused --rounds 3 --no-charts \
  --no-detail --out-dir /tmp/bench > $OUT/bench.log 2>&1 || echo "bench exit $?" >> $OUT/errors.txt
cp /tmp/bench/results.csv $OUT/bench.csv
tar -cJf $OUT/bench.tar.xz -C /tmp bench
echo done
