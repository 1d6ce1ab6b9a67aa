#!/usr/bin/env bash
B=/work/main/build/raylab; S=/work/shared/scenes/Sponza/Sponza.gltf
out=/tmp/sw/sweep4.csv; rm -f $out
run() { # case mode F flat
  local c=$1 m=$2 f=$3 fl=$4
  n=$(basename "${c%%@*}" .gltf)-${c#*@}
  RL_PRESPLIT_FLAT=$fl RL_PRESPLIT_MODE=$m timeout 900 nice $B tracebench --scene "${c%%@*}" --view "${c#*@}" --size 1024x512 --bvhs sbvh --bvh-presplit $f \
    --repeat 1 --warmup 0 --check 512 --csv /tmp/sw/t4.csv > /tmp/sw/t4.txt 2>&1 || echo "fail $n $m $f" >> /tmp/sw/errors4
  [ -s $out ] || head -1 /tmp/sw/t4.csv | sed 's/^/case,mode,presplit,/' > $out
  tail -n +2 /tmp/sw/t4.csv | sed "s/^/$n,$m$fl,$f,/" >> $out
}
run "$S@CameraMain" mid 0 0
for fl in 0.00001 0.0001 0.0003 0.003; do run "$S@CameraMain" noflat 0.001 $fl; done
for c in temple@openings clutter:200000@overview temple-detail:200000@hall; do
  run "$c" mid 0 0; run "$c" noflat 0.001 0;
done
echo done > /tmp/sw/done4
