#!/usr/bin/env bash
# Local lavapipe sweep of --bvh-presplit: steps a ray and warp efficiency (device-independent), 1024x512.
B=/work/main/build/raylab; S=/work/shared/scenes/Sponza/Sponza.gltf
out=/tmp/sweep/sweep.csv; rm -f $out
for c in "$S@CameraMain" temple@hall temple@openings temple-detail:200000@hall; do
  for f in 0 0.0003 0.001 0.003 0.01; do
    n=$(basename "${c%%@*}" .gltf)-${c#*@}
    timeout 900 nice $B tracebench --scene "${c%%@*}" --view "${c#*@}" --size 1024x512 --bvhs sbvh --bvh-presplit $f \
      --repeat 1 --warmup 0 --check 1024 --csv /tmp/sweep/t.csv > /tmp/sweep/t.txt 2>&1 || echo "fail $n $f" >> /tmp/sweep/errors
    [ -s $out ] || head -1 /tmp/sweep/t.csv | sed 's/^/case,presplit,/' > $out
    tail -n +2 /tmp/sweep/t.csv | sed "s/^/$n,$f,/" >> $out
  done
done
echo done > /tmp/sweep/done
