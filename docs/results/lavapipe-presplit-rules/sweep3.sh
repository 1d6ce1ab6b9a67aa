#!/usr/bin/env bash
B=/work/main/build/raylab; S=/work/shared/scenes/Sponza/Sponza.gltf
out=/tmp/sw/sweep3.csv; rm -f $out
run() { # case mode F flat
  local c=$1 m=$2 f=$3 fl=$4
  n=$(basename "${c%%@*}" .gltf)-${c#*@}
  RL_PRESPLIT_FLAT=$fl RL_PRESPLIT_MODE=$m timeout 900 nice $B tracebench --scene "${c%%@*}" --view "${c#*@}" --size 1024x512 --bvhs sbvh --bvh-presplit $f \
    --repeat 1 --warmup 0 --check 512 --csv /tmp/sw/t3.csv > /tmp/sw/t3.txt 2>&1 || echo "fail $n $m $f" >> /tmp/sw/errors3
  [ -s $out ] || head -1 /tmp/sw/t3.csv | sed 's/^/case,mode,presplit,/' > $out
  tail -n +2 /tmp/sw/t3.csv | sed "s/^/$n,$m$fl,$f,/" >> $out
}
for c in "$S@CameraMain" temple@hall; do
  run "$c" mid 0 0
  for fl in 0 0.01 0.05; do run "$c" noflat 0.001 $fl; run "$c" noflat 0.01 $fl; done
done
run temple-detail:1000000@hall mid 0 0
for f in 0.001 0.003 0.01; do run temple-detail:1000000@hall noflat $f 0.001; done
echo done > /tmp/sw/done3
