#!/usr/bin/env bash
# For a session with the device (about 4 minutes): the committed presplit rule (axis-aligned triangles never cut)
# on the H200, F = 0 against 0.001, two rounds interleaved by process. Part 1 is issue 35's measure, the frame's
# trace stage (render --bounces 2 split, unsorted; rays/s of bounce 0 and 1, medians of frames 2-9:
# `python3 docs/results/h200-pair-nodes/analyse.py out/` over trees.tar.xz), with the megakernel on Sponza and the
# clutter room; part 2 the traversal alone (tracebench, 2048x1024, F = 0, 0.001, 0.003); part 3 the builds.
source docs/results/device-unpack.sh
B=build-device/raylab
t0=$SECONDS
run() {  # name F size mk scene args...
  local name=$1 f=$2 size=$3 mk=$4; shift 4
  $B render "$@" --bvh-presplit $f --size $size --bounces 2 --strategy none --compaction none --trace-shade split \
    --frames 10 --stats /tmp/out/$name-p$f-sbvh-$size-r$round.json --detail-every 0 --out /tmp/x.png > /dev/null 2>&1 \
    || echo "failed: $name $f $size" >> $OUT/errors.txt
  [ $mk = mk ] || return 0
  $B render "$@" --bvh-presplit $f --size $size --bounces 4 --kernel megakernel --frames 10 \
    --stats /tmp/mk/$name-p$f-sbvh-$size-r$round.json --detail-every 0 --out /tmp/x.png > /dev/null 2>&1 \
    || echo "failed: mk $name $f $size" >> $OUT/errors.txt
}
mkdir -p /tmp/mk /tmp/out
for round in 1 2; do
  for f in 0 0.001; do
    run sponza $f 2048x1024 mk --scene $S --view CameraMain
    run sponza $f 4096x2048 - --scene $S --view CameraMain
    run hall $f 2048x1024 - --scene temple --view hall
    run openings $f 2048x1024 - --scene temple --view openings
    run detail $f 2048x1024 - --scene temple-detail:1000000 --view hall
    run clutter $f 2048x1024 mk --scene clutter:1000000
    run cornell $f 2048x1024 - --scene .dev/cornell/cornellBox.gltf
  done
done
tar -cJf $OUT/trees.tar.xz -C /tmp out mk
echo "frames: $((SECONDS - t0)) s" >> $OUT/times.txt; t0=$SECONDS
for round in 1 2; do
  for c in "$S@CameraMain" temple@hall temple@openings temple-detail:1000000@hall clutter:1000000@overview \
           .dev/cornell/cornellBox.gltf@; do
    for f in 0 0.001 0.003; do
      [ $((SECONDS - t0)) -lt 150 ] || break 3
      n=$(basename "${c%%@*}" .gltf)-${c#*@}-p$f-r$round
      view=${c#*@}
      timeout 30 $B tracebench --scene "${c%%@*}" ${view:+--view $view} --size 2048x1024 --bvhs sbvh --bvh-presplit $f \
        --repeat 20 --check 1024 --csv /tmp/tb-$n.csv > /tmp/tb-$n.txt 2>&1 || echo "tracebench $n exit $?" >> $OUT/errors.txt
      appendRows /tmp/tb-$n.csv $OUT/tracebench.csv table,presplit,round $n,$f,$round
    done
  done
done
echo "tracebench: $((SECONDS - t0)) s" >> $OUT/times.txt; t0=$SECONDS
echo "scene,presplit,sbvh_build_ms,sbvh_sah_cost,sbvh_references" > $OUT/build.csv
for scene in "$S" temple-detail:10000000; do
  for f in 0 0.001; do
    timeout 100 $B render --scene "$scene" --size 64x32 --bvh-presplit $f --stats /tmp/b.json --out /tmp/b.png > /dev/null 2>&1 \
      || echo "build $scene $f exit $?" >> $OUT/errors.txt
    python3 -c "import json,sys; d=json.load(open('/tmp/b.json')); print(','.join([sys.argv[1].split('/')[-1], sys.argv[2]] + [str(d.get(k)) for k in ('sbvh_build_ms','sbvh_sah_cost','sbvh_references')]))" "$scene" $f >> $OUT/build.csv || true
  done
done
echo "builds: $((SECONDS - t0)) s" >> $OUT/times.txt
echo done
