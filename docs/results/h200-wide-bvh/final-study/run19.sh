#!/usr/bin/env bash
# Device session (issue 20, stop 33, after the hit-mask box tests): the invariant on the H200 through the command line, both collapses: every key
# strategy (radix, always) and auto render the unsorted wide image's PNG byte for byte.
set -x
for f in .gl/*.deb; do dpkg -x $f /; done; ldconfig
xz -dkf build-device/lib/*.xz
R=build-device/raylab
for how in sah greedy; do for c in temple@hall clutter:100000@overview; do
  scene=${c%@*}; view=${c#*@}; base="$R render --scene $scene --view $view --size 1024x512 --bounces 4 --frames 3 --bvh wide --wide-collapse $how"
  $base --out /tmp/u.png > /dev/null 2>&1 || echo "FAIL unsorted $how $c"
  for st in dead-last fixed average ema gaussian origin direction origin-direction two-point oracle; do
    $base --strategy $st --out /tmp/s.png > /dev/null 2>&1 || echo "FAIL render $how $c $st"
    cmp -s /tmp/u.png /tmp/s.png && echo "same $how $c $st" || echo "DIFFERENT $how $c $st"
  done
  $base --strategy two-point --sort-policy auto --trace-shade fused --out /tmp/s.png > /dev/null 2>&1
  cmp -s /tmp/u.png /tmp/s.png && echo "same $how $c two-point auto fused" || echo "DIFFERENT $how $c two-point auto fused"
  cp /tmp/u.png $OUT/unsorted-$how-${scene%%:*}.png
done; done > $OUT/invariant-cli.log 2>&1
echo done
