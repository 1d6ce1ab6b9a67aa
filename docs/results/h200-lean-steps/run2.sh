#!/usr/bin/env bash
# Two more steps over the kept one (`base` here is e7ac6b2, run.sh's `blenc`):
# `ed`    the pair test returns whether each box is entered (enter <= leave) beside the entry distances, where
#         the loop compared the distances with 1e30 after intersectPair had set a missed box's to it;
# `nb`    the push without its bound check (lost 3.5-6% of camera rays at f2ca16c: h200-traversal-top);
# `ednb`  both.
# Trace rates and the megakernel's Sponza frame as in run.sh; three interleaved rounds.
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
  for bin in base ed nb ednb; do
    run sponza $bin 2048x1024 mk --scene $S --view CameraMain
    run sponza $bin 4096x2048 - --scene $S --view CameraMain
    run hall $bin 2048x1024 - --scene temple --view hall
    run detail $bin 2048x1024 - --scene temple-detail:1000000
  done
  echo "round $round done at $SECONDS s"
  tar -cJf $OUT/lean.tar.xz -C /tmp out mk  # after every round: a run cut short still brings its rounds back
done
# The images: every variant renders Sponza as base does.
for bin in base ed nb ednb; do
  $(bin_of $bin) render --scene $S --view CameraMain --size 1024x512 --bounces 4 --frames 1 --out /tmp/img-$bin.png > /dev/null 2>&1
  cmp /tmp/img-base.png /tmp/img-$bin.png >> $OUT/images.txt 2>&1 && echo "$bin = base" >> $OUT/images.txt
done
echo done
