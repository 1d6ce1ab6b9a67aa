#!/usr/bin/env bash
# Device session (issue 20): the BVH builds of both collapses on 16 cores.
set -x
for f in .carry/gl/*.deb; do dpkg -x $f /; done; ldconfig
xz -dkf build-device/lib/*.xz
B=build-device
for how in greedy sah; do
  ( time timeout 60 $B/tests/raylab_bvh_report --repeats 3 --wide-collapse $how temple-detail:1000000 clutter:1000000 temple-detail:10000000 ) 2>&1 | grep -v "^warning" >> $OUT/bvh.jsonl
done
echo done
