#!/usr/bin/env bash
# The committed rule (axis-aligned triangles never cut, kPresplitFlatness) on lavapipe: steps a ray and warp
# efficiency at 1024x512 for --bvh-presplit 0, 0.001, 0.003 and 0.01 on the five scenes.
B=${B:-/work/main/build/raylab}; S=${S:-/work/shared/scenes/Sponza/Sponza.gltf}; W=${W:-/tmp/sw}
out=$W/final.csv; rm -f $out
for c in "$S@CameraMain" temple@hall temple@openings temple-detail:200000@hall clutter:200000@overview; do
  for f in 0 0.001 0.003 0.01; do
    n=$(basename "${c%%@*}" .gltf)-${c#*@}
    timeout 900 nice $B tracebench --scene "${c%%@*}" --view "${c#*@}" --size 1024x512 --bvhs sbvh --bvh-presplit $f \
      --repeat 1 --warmup 0 --check 512 --csv $W/tf.csv > $W/tf.txt 2>&1 || echo "fail $n $f" >> $W/errors-final
    [ -s $out ] || head -1 $W/tf.csv | sed 's/^/case,mode,presplit,/' > $out
    tail -n +2 $W/tf.csv | sed "s/^/$n,rule,$f,/" >> $out
  done
done
echo done > $W/done-final
