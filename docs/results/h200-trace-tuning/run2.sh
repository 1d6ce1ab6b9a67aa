#!/usr/bin/env bash
# Step counting only where read (RL_SPEC_COUNTS_STEPS): `base` (b3b7baa, every traversal counts its steps)
# against `steps` (the trace and the megakernel count only on detailed frames and under a heatmap). The trace
# stage's rays per second as run.sh measures them, and the megakernel's stage time (`--kernel megakernel`,
# 4 bounces), Sponza at 2048x1024 and 4096x2048, the hall, temple-detail:1000000 and clutter:1000000 at
# 2048x1024; three interleaved rounds.
source docs/results/device-unpack.sh
run() {  # name binary size scene args...
  local name=$1 bin=$2 size=$3; shift 3
  .dev/$bin/raylab render "$@" --size $size --bounces 2 --strategy none --compaction none --trace-shade split \
    --frames 12 --stats /tmp/out/$name-$bin-sbvh-$size-r$round.json --detail-every 0 --out /tmp/x.png \
    > /dev/null 2>&1 || echo "failed: $name $bin $size" >> $OUT/errors.txt
  .dev/$bin/raylab render "$@" --size $size --bounces 4 --kernel megakernel --frames 12 \
    --stats /tmp/mk/$name-$bin-$size-r$round.json --detail-every 0 --out /tmp/x.png \
    > /dev/null 2>&1 || echo "failed: mk $name $bin $size" >> $OUT/errors.txt
}
mkdir -p /tmp/mk
for round in 1 2 3; do
  for bin in base steps; do
    run sponza $bin 2048x1024 --scene $S --view CameraMain
    run sponza $bin 4096x2048 --scene $S --view CameraMain
    run hall $bin 2048x1024 --scene temple --view hall
    run detail $bin 2048x1024 --scene temple-detail:1000000 --view hall
    run clutter $bin 2048x1024 --scene clutter:1000000
  done
done
tar -cJf $OUT/steps.tar.xz -C /tmp out mk
echo done
