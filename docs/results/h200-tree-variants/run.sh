#!/usr/bin/env bash
# Device call A (issue 35), about 8 minutes: the traversal alone on every tree (tracebench), the reinsertion A/B
# (--bvh-reinsert 0 against 5, separate processes, interleaved), and the spatial-split build with and without it on
# the 16 cores. Device: source docs/results/device-unpack.sh (gives $S). Local check: LOCAL=1 OUT=/tmp/x bash this.
if [ -n "${LOCAL:-}" ]; then
  B=build/raylab; S=/work/shared/scenes/Sponza/Sponza.gltf; mkdir -p $OUT
  SIZE2=128x64; SIZE4=256x128; REP=2; BIG=temple-detail:100000
else
  source docs/results/device-unpack.sh
  B=build-device/raylab; SIZE2=2048x1024; SIZE4=4096x2048; REP=20; BIG=temple-detail:10000000
fi
small() { local c=$1; [ -n "${LOCAL:-}" ] && { [ "${c#clutter}" != "$c" ] && c=clutter:50000@overview; [ "${c#temple-detail}" != "$c" ] && c=temple-detail:20000@hall; }; echo $c; }
t0=$SECONDS
tb() {  # tb NAME ARGS...: one tracebench table appended to tracebench.csv, its name in the first column
  local name=$1; shift
  timeout 150 $B tracebench "$@" --repeat $REP --csv /tmp/tb-$name.csv > /tmp/tb-$name.txt 2>&1 || echo "tracebench $name exit $?" >> $OUT/errors.txt
  [ -s $OUT/tracebench.csv ] || head -1 /tmp/tb-$name.csv | sed 's/^/table,/' > $OUT/tracebench.csv
  tail -n +2 /tmp/tb-$name.csv | sed "s/^/$name,/" >> $OUT/tracebench.csv
  cat /tmp/tb-$name.txt >> $OUT/tracebench.txt
}
# 1. Every tree, Sponza at both sizes (the issue's table), scanline camera rays, the study's scenes.
tb sponza2k --scene $S --view CameraMain --size $SIZE2 --bvhs sbvh,binary,wide --sort-rays two-point
tb sponza2k-scanline --scene $S --view CameraMain --size $SIZE2 --bvhs sbvh --order scanline --kinds camera
tb sponza4k --scene $S --view CameraMain --size $SIZE4 --bvhs sbvh,binary
for c in temple@hall temple@openings temple-detail:1000000@hall clutter:1000000@overview; do
  c=$(small $c); tb "${c%%@*}-${c#*@}" --scene "${c%%@*}" --view "${c#*@}" --size $SIZE2 --bvhs sbvh,binary --sort-rays two-point
done
echo "tracebench: $((SECONDS - t0)) s" >> $OUT/times.txt
# 2. The reinsertion A/B: the sbvh tree as Embree builds it (0) and after 5 passes (5), two rounds interleaved.
t1=$SECONDS
for r in 1 2; do
  for n in 0 5; do
    tb "sponza2k-r$n-$r" --scene $S --view CameraMain --size $SIZE2 --bvhs sbvh --bvh-reinsert $n
    tb "sponza4k-r$n-$r" --scene $S --view CameraMain --size $SIZE4 --bvhs sbvh --bvh-reinsert $n --kinds camera,bounce
    for c in temple@hall temple-detail:1000000@hall clutter:1000000@overview; do
      c=$(small $c); tb "${c%%@*}-${c#*@}-r$n-$r" --scene "${c%%@*}" --view "${c#*@}" --size $SIZE2 --bvhs sbvh --bvh-reinsert $n
    done
  done
done
echo "reinsert A/B: $((SECONDS - t1)) s" >> $OUT/times.txt
# 2b. Presplitting (docs/results/lavapipe-tree-steps/presplit.patch built as .dev/presplit/raylab), the largest 0.1% of
# references cut before Embree's build, against this binary, two rounds interleaved (Sponza, the hall, temple-detail).
PRE=.dev/presplit/raylab; [ -n "${LOCAL:-}" ] && PRE=${PREBIN:-}
if [ -n "$PRE" ] && [ -x "$PRE" ]; then
  t3=$SECONDS
  for r in 1 2; do
    for v in base pre; do
      bin=$B; [ $v = pre ] && bin=$PRE
      for c in "$S@CameraMain" temple@hall temple-detail:1000000@hall; do
        c=$(small "$c"); n=$(basename "${c%%@*}" .gltf)-${c#*@}-$v-$r
        B=$bin RL_PRESPLIT_AREA=1 RL_PRESPLIT=0.001 tb "$n" --scene "${c%%@*}" --view "${c#*@}" --size $SIZE2 --bvhs sbvh
      done
    done
  done
  echo "presplit A/B: $((SECONDS - t3)) s" >> $OUT/times.txt
fi
# 3. The spatial-split build on the 16 cores (issue 35: Sponza at most 0.3 s, temple-detail:10000000 at most 3 s).
t2=$SECONDS
echo "scene,bvh_reinsert,sbvh_build_ms,sbvh_sah_cost,sbvh_nodes,sbvh_references,bvh_build_ms,wall_s" > $OUT/build.csv
for scene in "$S" $BIG; do
  for n in 0 5; do
    s0=$SECONDS
    timeout 120 $B render --scene "$scene" --size 64x32 --bvh-reinsert $n --stats /tmp/b.json --out /tmp/b.png > /dev/null 2>&1 || echo "build $scene $n exit $?" >> $OUT/errors.txt
    python3 -c "import json,sys; d=json.load(open('/tmp/b.json')); print(','.join([sys.argv[1].split('/')[-1], sys.argv[2]] + [str(d.get(k)) for k in ('sbvh_build_ms','sbvh_sah_cost','sbvh_nodes','sbvh_references','bvh_build_ms')] + [sys.argv[3]]))" "$scene" $n $((SECONDS - s0)) >> $OUT/build.csv || true
  done
done
echo "builds: $((SECONDS - t2)) s" >> $OUT/times.txt
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt 2>&1 || true
echo done
