#!/usr/bin/env bash
# Two leaner steps of the binary traversal (issue 35), each alone and together, against `base` (315c5e0):
# `bl`    the triangle test without early exits: u, v and t computed, then one test (no |det| epsilon);
# `enc`   pair nodes store a leaf child's word (RL_LEAF_TAG, first entry, count - 1) ready, so a node's
#         iteration no longer builds it, and no longer checks for RL_BVH_NO_CHILD;
# `blenc` both.
# The trace stage's rays per second per bounce (render --trace-shade split, 2 bounces, unsorted), and the
# megakernel's frame (4 bounces) on Sponza and the clutter room; three interleaved rounds, 10 frames each (the
# analysis drops the first two).
source docs/results/device-unpack.sh
bin_of() { [ "$1" = base ] && echo build-device/raylab || echo .dev/$1/raylab; }
run() {  # name binary size megakernel-too scene args...
  local name=$1 bin=$2 size=$3 mk=$4; shift 4
  local exe; exe=$(bin_of $bin)
  $exe render "$@" --size $size --bounces 2 --strategy none --compaction none --trace-shade split \
    --frames 10 --stats /tmp/out/$name-$bin-sbvh-$size-r$round.json --detail-every 0 --out /tmp/x.png \
    > /dev/null 2>&1 || echo "failed: $name $bin $size" >> $OUT/errors.txt
  [ $mk = mk ] || return 0
  $exe render "$@" --size $size --bounces 4 --kernel megakernel --frames 10 \
    --stats /tmp/mk/$name-$bin-sbvh-$size-r$round.json --detail-every 0 --out /tmp/x.png \
    > /dev/null 2>&1 || echo "failed: mk $name $bin $size" >> $OUT/errors.txt
}
mkdir -p /tmp/mk
for round in 1 2 3; do
  for bin in base bl enc blenc; do
    run sponza $bin 2048x1024 mk --scene $S --view CameraMain
    run sponza $bin 4096x2048 - --scene $S --view CameraMain
    run hall $bin 2048x1024 - --scene temple --view hall
    run detail $bin 2048x1024 - --scene temple-detail:1000000
    run clutter $bin 2048x1024 mk --scene clutter:1000000
  done
  echo "round $round done at $SECONDS s"
  tar -cJf $OUT/lean.tar.xz -C /tmp out mk  # after every round: a run cut short still brings its rounds back
done
# The images: every variant renders Sponza as base does, or as near as a changed triangle test allows.
for bin in base bl enc blenc; do
  $(bin_of $bin) render --scene $S --view CameraMain --size 1024x512 --bounces 4 --frames 1 --out /tmp/img-$bin.png > /dev/null 2>&1
done
cmp /tmp/img-base.png /tmp/img-enc.png > $OUT/images.txt 2>&1 && echo "enc = base" >> $OUT/images.txt
cmp /tmp/img-bl.png /tmp/img-blenc.png >> $OUT/images.txt 2>&1 && echo "blenc = bl" >> $OUT/images.txt
cmp /tmp/img-base.png /tmp/img-bl.png >> $OUT/images.txt 2>&1 && echo "bl = base" >> $OUT/images.txt
echo done
