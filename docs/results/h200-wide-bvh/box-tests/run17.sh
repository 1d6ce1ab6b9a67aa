#!/usr/bin/env bash
# Device session (issue 20, stop 33): the wide node's box tests setting one bit a slot, the interior bits put in
# visit order once per node and the leaves' triangle masks built only for the leaves hit (hitmask), or in the
# unrolled loop as before (hitmaskb), against main (base3); two rounds alternating, 4096x2048, 4 bounces.
set -x
for f in .gl/*.deb; do dpkg -x $f /; done; ldconfig
xz -dkf build-device/lib/*.xz
mkdir -p .dev/lib && cp build-device/lib/* .dev/lib/
S=.dev/sponza/Sponza.gltf
for v in base3 hitmask hitmaskb; do
  RAYLAB_SHADER_STATS=1 .dev/bin/raylab-$v render --scene $S --size 256x128 --frames 1 --bvh wide --out /tmp/s.png 2>&1 \
    | grep -E "shader-stats (trace|shade)" | sed "s/^/$v /" >> $OUT/shader-stats.txt  # shader-stats-hitmask.txt here
done
for round in 1 2; do for v in base3 hitmask hitmaskb; do
  ( time timeout 120 .dev/bin/raylab-$v bench --cases temple@hall,$S@CameraMain,temple-detail:1000000@hall \
      --bvhs wide --strategies two-point --sort-policies always --trace-shades split --sizes 4096x2048 \
      --bounces 4 --timed-frames 8 --warmup 3 --reference-spp 1 --no-detail --no-charts --out-dir /tmp/$v-$round ) \
      >> $OUT/hitmask.log 2>&1
  sed "s/^/$v,$round,/" /tmp/$v-$round/results.csv >> $OUT/hitmask.csv
done; done
echo done
