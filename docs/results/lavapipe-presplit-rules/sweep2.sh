#!/usr/bin/env bash
# lavapipe count sweep of presplit plane modes
B=/work/main/build/raylab; S=/work/shared/scenes/Sponza/Sponza.gltf
out=/tmp/sw/sweep2.csv; rm -f $out /tmp/sw/errors
run() { # case mode F
  local c=$1 m=$2 f=$3
  n=$(basename "${c%%@*}" .gltf)-${c#*@}
  RL_PRESPLIT_MODE=$m timeout 900 nice $B tracebench --scene "${c%%@*}" --view "${c#*@}" --size 1024x512 --bvhs sbvh --bvh-presplit $f \
    --repeat 1 --warmup 0 --check 512 --csv /tmp/sw/t2.csv > /tmp/sw/t2.txt 2>&1 || echo "fail $n $m $f" >> /tmp/sw/errors
  [ -s $out ] || head -1 /tmp/sw/t2.csv | sed 's/^/case,mode,presplit,/' > $out
  tail -n +2 /tmp/sw/t2.csv | sed "s/^/$n,$m,$f,/" >> $out
}
for c in "$S@CameraMain" temple@hall temple@openings temple-detail:200000@hall clutter:200000@overview; do
  run "$c" mid 0
  for f in 0.001 0.003 0.01 0.03; do for m in gain gain3 noflat; do run "$c" $m $f; done; done
done
echo done > /tmp/sw/done2
