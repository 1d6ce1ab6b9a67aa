#!/usr/bin/env bash
# Third device call, at the session's last revision: the invariant on the H200 through the command line with
# the detailed statistics' passes on (--stats, every frame) and the binary tree's pair nodes: every key
# strategy renders the unsorted image's PNG byte for byte, on both trees, on the temple's hall and Sponza,
# and along a camera path with a cut; then a bench with 3 interleaved rounds. Carry as run.sh says.
tar -xJf .dev/bins.tar.xz
for f in .dev/carry/gl/*.deb; do dpkg -x $f /; done; ldconfig
xz -dkf build-device/lib/*.xz
R=build-device/raylab
S=.dev/sponza/Sponza.gltf
for bvh in binary wide; do for c in temple@hall $S@CameraMain; do
  scene=${c%@*}; view=${c#*@}
  base="$R render --scene $scene --view $view --size 1024x512 --bounces 4 --frames 3 --bvh $bvh"
  $base --out /tmp/u.png > /dev/null 2>&1 || echo "FAIL unsorted $bvh $c"
  for st in dead-last fixed average gaussian origin-direction two-point oracle; do
    $base --strategy $st --stats /tmp/s.json --out /tmp/s.png > /dev/null 2>&1 || echo "FAIL render $bvh $c $st"
    cmp -s /tmp/u.png /tmp/s.png && echo "same $bvh $(basename $scene) $st" || echo "DIFFERENT $bvh $(basename $scene) $st"
  done
  $base --strategy two-point --sort-policy auto --trace-shade fused --out /tmp/s.png > /dev/null 2>&1
  cmp -s /tmp/u.png /tmp/s.png && echo "same $bvh $(basename $scene) two-point auto fused" || echo "DIFFERENT $bvh $(basename $scene) two-point auto fused"
done; done > $OUT/invariant-cli.log 2>&1
for st in average two-point; do  # the camera path: the last frame after a cut
  $R render --camera-path builtin:cut --frames 40 --size 1024x512 --bounces 4 --out /tmp/pu.png > /dev/null 2>&1
  $R render --camera-path builtin:cut --frames 40 --size 1024x512 --bounces 4 --strategy $st --stats /tmp/p.json \
    --out /tmp/ps.png > /dev/null 2>&1
  cmp -s /tmp/pu.png /tmp/ps.png && echo "same camera path cut $st" || echo "DIFFERENT camera path cut $st"
done >> $OUT/invariant-cli.log 2>&1
( time $R bench --cases $S@CameraMain --strategies two-point --sizes 2048x1024,4096x2048 --bounces 4 --rounds 3 \
    --out-dir /tmp/bench --no-charts ) > $OUT/bench.log 2>&1
tar -cJf $OUT/bench.tar.xz -C /tmp bench
echo done
