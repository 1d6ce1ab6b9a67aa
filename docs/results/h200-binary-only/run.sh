#!/usr/bin/env bash
# A trace shader with the binary traversal alone (issue 35): `base` (f2ca16c: traverseSceneBvh branches on
# GpuScene::bvhLayout at run time, so every pipeline that traces holds both the binary and the wide traversal)
# against `binonly` (the same with the wide branch removed). First the compiler's statistics of each pipeline
# (RAYLAB_SHADER_STATS=1: registers, local and shared memory), then the trace stage's rays per second per bounce
# (render --trace-shade split, 2 bounces, unsorted) and the megakernel's frame (4 bounces; Sponza 2048x1024 and
# the clutter room), Sponza at 2048x1024 and 4096x2048, the hall and clutter:1000000 at 2048x1024; three
# interleaved rounds, 10 frames each (the analysis drops the first two).
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
for bin in base binonly; do
  for kernel in "--trace-shade split --strategy none" "--kernel megakernel"; do
    RAYLAB_SHADER_STATS=1 $(bin_of $bin) render --scene $S --view CameraMain --size 256x128 --bounces 2 $kernel \
      --frames 1 --out /tmp/x.png 2>&1 | grep shader-stats | sed "s/^/$bin /" >> $OUT/shader-stats.txt
  done
done
for round in 1 2 3; do
  for bin in base binonly; do
    run sponza $bin 2048x1024 mk --scene $S --view CameraMain
    run sponza $bin 4096x2048 - --scene $S --view CameraMain
    run hall $bin 2048x1024 - --scene temple --view hall
    run clutter $bin 2048x1024 mk --scene clutter:1000000
  done
  echo "round $round done at $SECONDS s"
  tar -cJf $OUT/binonly.tar.xz -C /tmp out mk  # after every round: a run cut short still brings its rounds back
done
echo done
