#!/usr/bin/env bash
# Device session (issue 20): the binary BVH's frames under each collapse's triangle order.
set -x
for f in .gl/*.deb; do dpkg -x $f /; done; ldconfig
xz -dkf build-device/lib/*.xz
S=.dev/sponza/Sponza.gltf
for how in greedy sah greedy; do
  ( time timeout 150 build-device/raylab bench --wide-collapse $how \
    --cases temple@hall,$S@CameraMain,temple-detail:1000000@hall,clutter:1000000@overview \
    --strategies two-point --sort-policies always --trace-shades split --bvhs binary \
    --sizes 4096x2048 --bounces 4 --timed-frames 8 --warmup 4 --reference-spp 1 \
    --no-detail --no-charts --out-dir /tmp/b-$how ) >> $OUT/binary.log 2>&1
  sed "s/^/$how,/" /tmp/b-$how/results.csv >> $OUT/binary-order.csv
  rm -rf /tmp/b-$how
done
echo done
