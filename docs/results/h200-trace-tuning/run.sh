#!/usr/bin/env bash
# Issue 35, the last gap: small changes to the trace measured against the traversal of 8806882 (`base`), one
# device call, five binaries (.dev/NAME/raylab) built from 8806882 with one change each:
#   mtdefer  Moeller-Trumbore with u, v and t tested against |det| first: only a hit pays the division;
#   wg128    RL_PATH_GROUP_SIZE 128 (every path stage's work group; base has 64);
#   wg32     RL_PATH_GROUP_SIZE 32;
#   nosteps  the traversal's step count left out (what counting steps for the heatmaps costs).
# The trace stage's rays per second as in ../h200-traversal/run.sh: 2 bounces, unsorted, split, no compaction,
# sbvh; Sponza at 2048x1024 and 4096x2048, the hall, temple-detail:1000000 and clutter:1000000 at 2048x1024.
# Three interleaved rounds.
source docs/results/device-unpack.sh  # also sets S (Sponza), makes /tmp/out, writes $OUT/gpu.txt
run() {  # name binary size scene args...
  local name=$1 bin=$2 size=$3; shift 3
  .dev/$bin/raylab render "$@" --size $size --bounces 2 --strategy none --compaction none --trace-shade split \
    --bvh sbvh --frames 12 --stats /tmp/out/$name-$bin-sbvh-$size-r$round.json --detail-every 0 \
    --out /tmp/x.png > /dev/null 2>&1 || echo "failed: $name $bin $size" >> $OUT/errors.txt
}
for round in 1 2 3; do
  for bin in base mtdefer wg128 wg32 nosteps; do
    run sponza $bin 2048x1024 --scene $S --view CameraMain
    run sponza $bin 4096x2048 --scene $S --view CameraMain
    run hall $bin 2048x1024 --scene temple --view hall
    run detail $bin 2048x1024 --scene temple-detail:1000000 --view hall
    run clutter $bin 2048x1024 --scene clutter:1000000
  done
done
tar -cJf $OUT/trace.tar.xz -C /tmp out
echo done
