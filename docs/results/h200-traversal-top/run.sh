#!/usr/bin/env bash
# The binary traversal's stack (issue 35): `base` (f2ca16c: a bound check on every push, the whole stack in
# local memory), `nobound` (no bound check: the host keeps every tree within RL_BVH_STACK) and `top` (no bound
# check, and the stack's top entry in a register so that a pop hands over the next node without a load).
# The trace stage's rays per second per bounce (render --trace-shade split, 2 bounces, unsorted) and the
# megakernel's frame (4 bounces; Sponza 2048x1024 and the clutter room), Sponza at 2048x1024 and 4096x2048, the
# hall and clutter:1000000 at 2048x1024; three interleaved rounds, 10 frames each (the analysis drops the first
# two). Sized for the 643 s of device time this session had left.
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
  for bin in base nobound top; do
    run sponza $bin 2048x1024 mk --scene $S --view CameraMain
    run sponza $bin 4096x2048 - --scene $S --view CameraMain
    run hall $bin 2048x1024 - --scene temple --view hall
    run clutter $bin 2048x1024 mk --scene clutter:1000000
  done
  echo "round $round done at $SECONDS s"
  tar -cJf $OUT/top.tar.xz -C /tmp out mk  # after every round: a run cut short still brings its rounds back
done
echo done
