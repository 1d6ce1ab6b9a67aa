#!/usr/bin/env bash
# Issue 35, the loop: which traversal of the pair-node tree is fastest on the H200. One device call, four
# binaries built from one revision's code with only the traversal changed (.dev/NAME/raylab):
#   base  the traversal before (leaves intersected in their parent's iteration, both children's in turn);
#   ro    base with the tree's buffers readonly restrict (NonWritable: the driver may read them through the
#         read-only data path);
#   leaf  ro with a leaf visited like a node (one iteration, one triangle loop in the code);
#   ww    leaf as Aila and Laine's while-while loop with postponed leaves (the subgroup intersects together).
# The trace stage's rays per second (bounce 0 = camera rays, bounce 1 = the first bounce), 2 bounces,
# unsorted, split, no compaction; Sponza at 2048x1024 and 4096x2048, the hall, temple-detail:1000000 and the
# clutter room at 1e6 triangles at 2048x1024; sbvh, and base also on the binary tree without splits (the
# issue's "no scene slower than today's binary BVH"). Three interleaved rounds.
source docs/results/device-unpack.sh  # also sets S (Sponza), makes /tmp/out, writes $OUT/gpu.txt
run() {  # name binary bvh size scene args...
  local name=$1 bin=$2 bvh=$3 size=$4; shift 4
  .dev/$bin/raylab render "$@" --size $size --bounces 2 --strategy none --compaction none --trace-shade split \
    --bvh $bvh --frames 12 --stats /tmp/out/$name-$bin-$bvh-$size-r$round.json --detail-every 0 \
    --out /tmp/x.png > /dev/null 2>&1 || echo "failed: $name $bin $bvh $size" >> $OUT/errors.txt
}
for round in 1 2 3; do
  for cfg in base:binary base:sbvh ro:sbvh leaf:sbvh ww:sbvh; do
    bin=${cfg%:*} bvh=${cfg#*:}
    run sponza $bin $bvh 2048x1024 --scene $S --view CameraMain
    run sponza $bin $bvh 4096x2048 --scene $S --view CameraMain
    run hall $bin $bvh 2048x1024 --scene temple --view hall
    run detail $bin $bvh 2048x1024 --scene temple-detail:1000000 --view hall
    run clutter $bin $bvh 2048x1024 --scene clutter:1000000
  done
done
tar -cJf $OUT/trace.tar.xz -C /tmp out
echo done
