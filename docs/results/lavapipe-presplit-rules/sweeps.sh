#!/usr/bin/env bash
# The lavapipe count sweeps of the presplit rules (README), as they ran: the prototype (prototype.patch applied to
# e5756e5) reads RL_PRESPLIT_MODE (mid | grid | gridw | gain | gain3 | noflat) and RL_PRESPLIT_FLAT (noflat's
# threshold, default 1e-3). `bash sweeps.sh N` runs sweep N into $W/sweepN.csv (sweep 1 is sweep.csv).
B=${B:-/work/main/build/raylab}; S=${S:-/work/shared/scenes/Sponza/Sponza.gltf}; W=${W:-/tmp/sw}
n=$1; out=$W/sweep${n/#1/}.csv; rm -f $out
run() {  # case mode F [flatness]
  local c=$1 m=$2 f=$3 fl=${4:-}
  local name=$(basename "${c%%@*}" .gltf)-${c#*@}
  env ${fl:+RL_PRESPLIT_FLAT=$fl} RL_PRESPLIT_MODE=$m timeout 900 nice $B tracebench --scene "${c%%@*}" --view "${c#*@}" \
    --size 1024x512 --bvhs sbvh --bvh-presplit $f --repeat 1 --warmup 0 --check 512 --csv $W/t$n.csv > $W/t$n.txt 2>&1 \
    || echo "fail $name $m $f" >> $W/errors$n
  [ -s $out ] || head -1 $W/t$n.csv | sed 's/^/case,mode,presplit,/' > $out
  tail -n +2 $W/t$n.csv | sed "s/^/$name,$m$fl,$f,/" >> $out
}
five=("$S@CameraMain" temple@hall temple@openings temple-detail:200000@hall clutter:200000@overview)
case $n in
  1|2) modes="mid grid gridw"; [ $n = 2 ] && modes="gain gain3 noflat"
     for c in "${five[@]}"; do
       run "$c" mid 0
       for f in 0.001 0.003 0.01 0.03; do for m in $modes; do run "$c" $m $f; done; done
     done;;
  3) for c in "$S@CameraMain" temple@hall; do
       run "$c" mid 0 0
       for fl in 0 0.01 0.05; do run "$c" noflat 0.001 $fl; run "$c" noflat 0.01 $fl; done
     done
     run temple-detail:1000000@hall mid 0 0
     for f in 0.001 0.003 0.01; do run temple-detail:1000000@hall noflat $f 0.001; done;;
  4) run "$S@CameraMain" mid 0 0
     for fl in 0.00001 0.0001 0.0003 0.003; do run "$S@CameraMain" noflat 0.001 $fl; done
     for c in temple@openings clutter:200000@overview temple-detail:200000@hall; do run "$c" mid 0 0; run "$c" noflat 0.001 0; done;;
  *) echo "usage: bash sweeps.sh 1|2|3|4" >&2; exit 2;;
esac
