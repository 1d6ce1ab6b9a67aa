#!/usr/bin/env bash
# Call E (issue 35): the committed --bvh-presplit F with tracebench at 2048x1024 on the five scenes of the study,
# F = 0, 0.01, 0.03, two rounds interleaved by process; the builds' ms come with each row's scene (stderr log).
source docs/results/device-unpack.sh
B=build-device/raylab
t0=$SECONDS
for round in 1 2; do
  for c in "$S@CameraMain" temple@hall temple@openings temple-detail:1000000@hall clutter:1000000@overview; do
    for f in 0 0.01 0.03; do
      [ $((SECONDS - t0)) -lt 170 ] || break 3
      n=$(basename "${c%%@*}" .gltf)-${c#*@}-p$f-r$round
      timeout 30 $B tracebench --scene "${c%%@*}" --view "${c#*@}" --size 2048x1024 --bvhs sbvh --bvh-presplit $f \
        --repeat 20 --check 1024 --csv /tmp/tb-$n.csv > /tmp/tb-$n.txt 2>&1 || echo "tracebench $n exit $?" >> $OUT/errors.txt
      [ -s $OUT/sweep.csv ] || head -1 /tmp/tb-$n.csv | sed 's/^/table,presplit,round,/' > $OUT/sweep.csv
      tail -n +2 /tmp/tb-$n.csv | sed "s/^/$n,$f,$round,/" >> $OUT/sweep.csv
      grep -h "BVH\|triangles" /tmp/tb-$n.txt | head -2 | sed "s/^/$n: /" >> $OUT/log.txt
    done
  done
done
echo "sweep: $((SECONDS - t0)) s" >> $OUT/times.txt
echo done
