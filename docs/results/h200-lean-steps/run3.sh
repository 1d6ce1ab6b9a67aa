#!/usr/bin/env bash
# The spatial-split tree's SAH weights and leaf size over the lean traversal (4ad3790), one binary that reads
# them from the environment (a build of 4ad3790 with bvh.cpp's traversalCost 1 and intersectionCost RL_IC,
# maxLeafSize RL_ML; not committed): `base` 1 and 8 (as committed), `ic05` 0.5, `ic15` 1.5, `ic2` 2, `ml4`
# leaves of at most 4 triangles, `ml16` at most 16. Trace rates as in run.sh, the megakernel's Sponza frame;
# two interleaved rounds (a screen: the spreads of run.sh and run2.sh were under 1%).
source docs/results/device-unpack.sh
env_of() { case $1 in base) echo "RL_IC=1";; ic05) echo "RL_IC=0.5";; ic15) echo "RL_IC=1.5";; ic2) echo "RL_IC=2";;
  ml4) echo "RL_ML=4";; ml16) echo "RL_ML=16";; esac; }
run() {  # name config size megakernel-too scene args...
  local name=$1 cfg=$2 size=$3 mk=$4; shift 4
  env $(env_of $cfg) .dev/ic/raylab render "$@" --size $size --bounces 2 --strategy none --compaction none \
    --trace-shade split --frames 10 --stats /tmp/out/$name-$cfg-sbvh-$size-r$round.json --detail-every 0 \
    --out /tmp/x.png > /dev/null 2>&1 || echo "failed: $name $cfg $size" >> $OUT/errors.txt
  [ $mk = mk ] || return 0
  env $(env_of $cfg) .dev/ic/raylab render "$@" --size $size --bounces 4 --kernel megakernel --frames 10 \
    --stats /tmp/mk/$name-$cfg-sbvh-$size-r$round.json --detail-every 0 --out /tmp/x.png \
    > /dev/null 2>&1 || echo "failed: mk $name $cfg $size" >> $OUT/errors.txt
}
mkdir -p /tmp/mk
for round in 1 2; do
  for cfg in base ic05 ic15 ic2 ml4 ml16; do
    run sponza $cfg 2048x1024 mk --scene $S --view CameraMain
    run sponza $cfg 4096x2048 - --scene $S --view CameraMain
    run hall $cfg 2048x1024 - --scene temple --view hall
    run detail $cfg 2048x1024 - --scene temple-detail:1000000
    run clutter $cfg 2048x1024 mk --scene clutter:1000000
  done
  echo "round $round done at $SECONDS s"
  tar -cJf $OUT/sah.tar.xz -C /tmp out mk
done
echo done
