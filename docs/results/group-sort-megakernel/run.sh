#!/usr/bin/env bash
# Call 1 (about 5 minutes; issue 36, an experiment): the megakernel reordering its paths within each work group
# between bounces by the direction cell of the next ray (RAYLAB_MK_GROUP_SORT=BITS:GROUP, shaders/megakernel.comp:
# 2^BITS x 2^BITS octahedral cells, work groups of GROUP), against the plain megakernel and the unsorted wavefront
# (bench --strategies none), two rounds interleaved.
source docs/results/device-unpack.sh
t0=$SECONDS
for round in 1 2; do
  for v in off 4:256 4:512 5:512 3:64; do
    e=$v; [ $v = off ] && e=
    RAYLAB_MK_GROUP_SORT=$e timeout 120 build-device/raylab bench --cases "$S@CameraMain,temple@hall,clutter:1000000" \
      --sizes 720p,4096x2048 --bounces 4 --strategies none --rounds 1 --reference-spp 4 --no-detail --no-charts \
      --out-dir /tmp/mk-$v-$round > /tmp/mk.log 2>&1 || { echo "mk $v exit $?" >> $OUT/errors.txt; tail -3 /tmp/mk.log >> $OUT/errors.txt; }
    appendRows /tmp/mk-$v-$round/results.csv $OUT/mk.csv round,group_sort $round,$v
    echo "$v $round: $((SECONDS - t0)) s"
  done
done
