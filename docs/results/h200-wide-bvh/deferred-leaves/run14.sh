#!/usr/bin/env bash
# Device session (issue 20): a wide node's leaves deferred behind nearer interior children (an experiment).
set -x
for f in .gl/*.deb; do dpkg -x $f /; done; ldconfig
xz -dkf build-device/lib/*.xz
mkdir -p .dev/lib && cp build-device/lib/* .dev/lib/
S=.dev/sponza/Sponza.gltf
for v in base2 defer base2 defer; do
  ( time timeout 110 .dev/bin/raylab-$v bench --cases $S@CameraMain,temple@hall,clutter:1000000@overview,temple-detail:1000000@hall \
    --strategies two-point --sort-policies always --bvhs wide --trace-shades split --sizes 4096x2048 --bounces 4 \
    --timed-frames 8 --warmup 4 --reference-spp 1 --no-detail --no-charts --out-dir /tmp/v-$v ) >> $OUT/defer.log 2>&1
  sed "s/^/$v,/" /tmp/v-$v/results.csv >> $OUT/defer.csv
  rm -rf /tmp/v-$v
done
echo done
