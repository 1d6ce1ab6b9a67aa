#!/usr/bin/env bash
# Issue 35, first step, one device call: the binary traversal over pair nodes (BvhPairNode, Aila-Laine's
# layout) against the traversal before it (BvhNode, each child fetched as a 32-byte scalar struct), and the
# wide tree for reference. The trace stage's rays per second per bounce from `render --stats`, unsorted,
# Sponza CameraMain, 2 bounces (camera rays, first bounce), no compaction, split trace and shade (the issue's
# command), 2048x1024 and 4096x2048, 12 frames each (frames 2 on kept); three interleaved rounds, the
# binaries alternating. Also the sorted frame (two-point, 4 bounces, default settings) for each.
# Carry .dev/bins.tar.xz (build-device/raylab: new; .dev/old/raylab: before; Sponza; the loader) and the
# Embree library, as h200-true-figures/run.sh says.
tar -xJf .dev/bins.tar.xz
for f in .dev/carry/gl/*.deb; do dpkg -x $f /; done; ldconfig
xz -dkf build-device/lib/*.xz
mkdir -p .dev/old/lib && cp build-device/lib/*.so* .dev/old/lib/
S=.dev/sponza/Sponza.gltf
mkdir -p /tmp/out
for round in 1 2 3; do
  for bin in old new; do
    B=$([ $bin = new ] && echo build-device/raylab || echo .dev/old/raylab)
    for size in 2048x1024 4096x2048; do
      for bvh in binary wide; do
        $B render --scene $S --view CameraMain --size $size --bounces 2 --strategy none --compaction none \
          --trace-shade split --bvh $bvh --frames 12 --stats /tmp/out/trace-$bin-$bvh-$size-r$round.json \
          --detail-every 0 --out /tmp/x.png > /dev/null 2>&1 || echo "failed: $bin $bvh $size" >> $OUT/errors.txt
      done
      $B render --scene $S --view CameraMain --size $size --bounces 4 --strategy two-point --bvh binary --frames 12 \
        --stats /tmp/out/sorted-$bin-binary-$size-r$round.json --detail-every 0 --out /tmp/x.png > /dev/null 2>&1 \
        || echo "failed: sorted $bin $size" >> $OUT/errors.txt
      $B render --scene $S --view CameraMain --size $size --bounces 4 --strategy none --bvh binary --frames 12 \
        --stats /tmp/out/unsorted-$bin-binary-$size-r$round.json --detail-every 0 --out /tmp/x.png > /dev/null 2>&1 \
        || echo "failed: unsorted $bin $size" >> $OUT/errors.txt
    done
  done
done
tar -cJf $OUT/stats.tar.xz -C /tmp out
echo done
