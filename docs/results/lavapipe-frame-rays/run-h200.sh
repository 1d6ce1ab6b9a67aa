#!/usr/bin/env bash
# For a session with the device (about 3 minutes): where the frame's trace stage loses 9-12% against the
# traversal alone (README). Three binaries of the same tree (.dev/bins.tar.xz): `base` (build-device/raylab),
# `l1` (.dev/lean-l1/raylab: lean-trace.patch with RL_LEAN_TRACE defined, the frame's fields by access chain and
# no steps written) and `l2` (.dev/lean-l2/raylab: also RL_LEAN_NO_COUNT, no ray-count atomics; its stats count
# 0 rays, so its rate is base's rays over its own trace time). Issue 35's measure, Sponza CameraMain, three rounds
# interleaved between the binaries, then tracebench's traversal alone on the same sizes. Read the frames with
# `python3 docs/results/h200-pair-nodes/analyse.py lean/` (l2's rows read 0: divide base's rays by its trace ms).
source docs/results/device-unpack.sh
t0=$SECONDS
mkdir -p /tmp/lean
for round in 1 2 3; do
  for v in base l1 l2; do
    bin=build-device/raylab; [ $v != base ] && bin=.dev/lean-$v/raylab
    for size in 2048x1024 4096x2048; do
      timeout 60 $bin render --scene $S --view CameraMain --size $size --bounces 2 --strategy none --compaction none \
        --trace-shade split --frames 10 --detail-every 0 --stats /tmp/lean/sponza-$v-sbvh-$size-r$round.json --out /tmp/x.png \
        > /dev/null 2>&1 || echo "render $v $size $round exit $?" >> $OUT/errors.txt
    done
  done
done
tar -cJf $OUT/lean.tar.xz -C /tmp lean
echo "frames: $((SECONDS - t0)) s" >> $OUT/times.txt; t0=$SECONDS
for size in 2048x1024 4096x2048; do
  timeout 60 build-device/raylab tracebench --scene $S --view CameraMain --size $size --bvhs sbvh --kinds camera,bounce \
    --repeat 20 --check 1024 --csv /tmp/tb-$size.csv > /dev/null 2>&1 || echo "tracebench $size exit $?" >> $OUT/errors.txt
  appendRows /tmp/tb-$size.csv $OUT/tracebench.csv size $size
done
echo "tracebench: $((SECONDS - t0)) s" >> $OUT/times.txt
echo done
